#include "sweep/optimizer.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"
#include "util/random.h"

using namespace facetlight;

namespace {

// A smooth hill with its top at (40.63, 33.2), measured with noise that shrinks as 1/sqrt(photons) like a
// trace's, drawn independently at every point and photon count (harder than a sweep's common seed).
struct NoisyHill {
    double x0 = 40.63, y0 = 33.2;
    double truth(double x, double y) const {
        return 0.7 - std::pow((x - x0) / 3, 2) - std::pow((y - y0) / 8, 2);
    }
    GridObjective objective(std::function<bool(double, double)> feasible = {}) const {
        return [this, feasible](const std::vector<SweepAxis>& axes, uint64_t photons) {
            const double sigma = 0.02 / std::sqrt(double(photons) / 1e4);
            std::vector<DesignEstimate> out;
            for (double x : axes[0].values)
                for (double y : axes[1].values) {
                    Rng rng(photons,
                            uint64_t(std::llround(x * 1e3)) * 1000003 + uint64_t(std::llround(y * 1e3)));
                    // Box-Muller: a standard normal from two uniforms.
                    const double u = std::max(rng.uniformDouble(), 1e-12), v = rng.uniformDouble();
                    const double noise = std::sqrt(-2 * std::log(u)) * std::cos(2 * M_PI * v);
                    out.push_back({truth(x, y) + sigma * noise, sigma, !feasible || feasible(x, y)});
                }
            return out;
        };
    }
};

std::vector<SweepAxis> coarseGrid() {
    return {parseSweepAxis("pavilion=37:45:0.5"), parseSweepAxis("crown=25:40:1")};
}

// The round brilliant's sweep with `photons` a point on 2 threads, its axes for the search to set.
SweepPlan roundBrilliantSweep(uint64_t photons) {
    SweepPlan plan;
    plan.shape = "round_brilliant";
    plan.trace.photons = photons;
    plan.trace.threads = 2;
    return plan;
}

// Searches `figure` over the pavilion angles of `range` within `limits`, each round appended to `rounds`.
OptimizeResult searchPavilion(const SweepPlan& plan, const std::string& range, const std::string& figure,
                              const std::vector<SweepConstraint>& limits, int refineRounds,
                              std::vector<SweepResult>& rounds) {
    RunControl control;
    SerialCommunicator serial;
    OptimizeSettings settings;
    settings.refineRounds = refineRounds;
    return maximize({parseSweepAxis("pavilion=" + range)}, plan.trace.photons,
                    sweepObjective(plan, figure, limits, control, rounds, serial), settings);
}

}  // namespace

TEST(Optimizer, FindsTheTopOfANoisySmoothFunction) {
    const NoisyHill hill;
    const OptimizeResult r = maximize(coarseGrid(), 10000, hill.objective());
    ASSERT_EQ(r.best.values.size(), 2u);
    EXPECT_NEAR(r.best.values[0], hill.x0, 0.3);
    EXPECT_NEAR(r.best.values[1], hill.y0, 1.2);
    EXPECT_EQ(r.photons, 10000u * 64);
    EXPECT_NEAR(r.best.estimate.sigma, 0.02 / 8, 1e-12);
    // Its 95 % interval holds the true value there, and the ties are all within reach of it.
    EXPECT_NEAR(r.best.estimate.value, hill.truth(r.best.values[0], r.best.values[1]),
                3 * r.best.estimate.sigma);
    EXPECT_FALSE(
        r.ties.empty());  // a flat top: its neighbours a sixteenth of a degree away cannot be told apart
    for (const RatedDesign& t : r.ties)
        EXPECT_LE(r.best.estimate.value - t.estimate.value,
                  1.96 * std::sqrt(2.0) * r.best.estimate.sigma + 1e-12);
    EXPECT_EQ(r.evaluations, 17u * 16 + 3 * 25);
}

TEST(Optimizer, KeepsToTheConstraints) {
    const NoisyHill hill;
    const OptimizeResult r =
        maximize(coarseGrid(), 10000, hill.objective([](double x, double) { return x <= 40; }));
    EXPECT_LE(r.best.values[0], 40);
    EXPECT_NEAR(r.best.values[0], 40, 0.3);
    for (const RatedDesign& t : r.ties) EXPECT_LE(t.values[0], 40);
}

TEST(Optimizer, RefusesNamesAndImpossibleConstraints) {
    const NoisyHill hill;
    EXPECT_THROW(maximize({parseSweepAxis("material=diamond,bk7")}, 1000, hill.objective()), Error);
    EXPECT_THROW(maximize(coarseGrid(), 1000, hill.objective([](double, double) { return false; })), Error);
    EXPECT_EQ(parseSweepConstraint("total_depth<=62").quantity, "total_depth_pct");
    EXPECT_FALSE(parseSweepConstraint("crown_height_pct>=14").atMost);
    EXPECT_EQ(parseSweepConstraint("leakage<=0.1").quantity, "leakage");
    EXPECT_THROW(parseSweepConstraint("depth<=62"), Error);
    EXPECT_THROW(parseSweepConstraint("total_depth=62"), Error);
    EXPECT_THROW(parseSweepConstraint("total_depth<=deep"), Error);
}

// The real objective: a pavilion search under light straight down keeps to the depth limit, and its rounds
// are ordinary sweeps with more photons each.
TEST(Optimizer, SearchesASweepWithinADepthLimit) {
    std::vector<SweepResult> rounds;
    const OptimizeResult r = searchPavilion(roundBrilliantSweep(4000), "38:44:1", "weighted_return",
                                            {parseSweepConstraint("total_depth<=60")}, 1, rounds);
    ASSERT_EQ(rounds.size(), 2u);
    EXPECT_EQ(rounds[1].plan.trace.photons, 16000u);
    for (const SweepPoint& p : rounds[1].points)
        if (p.cut.at("pavilion") == r.best.values[0]) {
            EXPECT_LE(p.proportions["total_depth_pct"].get<double>(), 60);
        }
    EXPECT_GE(r.best.values[0], 38);
    EXPECT_LE(r.best.values[0], 41);  // deeper pavilions break the limit at this crown and girdle
}

// A fire figure is searched like any other, within a limit on another figure, once fire is traced.
TEST(Optimizer, SearchesAFireFigure) {
    SweepPlan plan = roundBrilliantSweep(3000);
    RunControl control;
    std::vector<SweepResult> rounds;
    SerialCommunicator serial;
    const std::vector<SweepConstraint> limits{parseSweepConstraint("weighted_return>=0.55")};
    EXPECT_THROW(sweepObjective(plan, "coloured_share", limits, control, rounds, serial), Error);  // fire off
    plan.trace.fire.enabled = true;
    const OptimizeResult r = searchPavilion(plan, "38:43:1", "coloured_share", limits, 0, rounds);
    ASSERT_EQ(rounds.size(), 1u);
    const std::vector<SweepPoint>& points = rounds[0].points;
    double highest = 0;
    for (const SweepPoint& p : points)
        if (p.figure("weighted_return") >= 0.55) highest = std::max(highest, p.figure("coloured_share"));
    EXPECT_EQ(r.best.estimate.value, highest);
    EXPECT_GT(highest, 0);
    EXPECT_LT(points.back().figure("weighted_return"), 0.55);  // the deepest breaks the limit
}
