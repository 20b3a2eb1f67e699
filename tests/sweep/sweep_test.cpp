#include "sweep/sweep_run.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <functional>
#include <mutex>

#include "scene/scene.h"
#include "stats/fire_stats.h"
#include "util/run_control.h"
#include "viewer/viewer_figures.h"
#include "sweep/sweep_figures.h"
#include "sweep/sweep_files.h"
#include "trace/photon_tracer.h"
#include "util/error.h"

using namespace facetlight;

namespace {

SweepPlan pavilionSweep(const std::string& range, uint64_t photons, int threads) {
    SweepPlan plan;
    plan.shape = "round_brilliant";
    plan.axes = {parseSweepAxis("pavilion=" + range)};
    plan.trace.photons = photons;
    plan.trace.threads = threads;
    return plan;
}

// Runs the sweep resumed from the kept points `restored` picks; returns it and the points it traced, in
// order.
std::pair<SweepResult, std::vector<size_t>> resumeSweep(const SweepPlan& plan, RunControl& control,
                                                        const std::vector<nlohmann::json>& kept,
                                                        const std::function<bool(size_t)>& restored) {
    std::vector<size_t> traced;
    std::mutex mutex;
    SweepPointHooks hooks;
    hooks.restore = [&](size_t k) { return restored(k) ? std::optional(kept[k]) : std::nullopt; };
    hooks.onPoint = [&](size_t k, const SweepPoint&) {
        std::lock_guard lock(mutex);
        traced.push_back(k);
    };
    SweepResult result = runSweep(plan, control, hooks);
    std::sort(traced.begin(), traced.end());
    return {std::move(result), traced};
}

nlohmann::json withoutTiming(const SweepResult& result) {
    nlohmann::json j = sweepToJson(result);
    j.erase("timing");
    j["settings"].erase("threads");
    return j;
}

}  // namespace

TEST(Sweep, ParsesRangesAndLists) {
    const SweepAxis range = parseSweepAxis("pavilion=37:38:0.1");
    ASSERT_EQ(range.values.size(), 11u);
    EXPECT_EQ(range.values[3], 37.3);  // the number a user typing 37.3 gets
    EXPECT_EQ(range.values.back(), 38.0);
    EXPECT_EQ(parseSweepAxis("crown=30,32.5").values, (std::vector<double>{30, 32.5}));
    EXPECT_EQ(parseSweepAxis("material=diamond,cubic_zirconia").choices,
              (std::vector<std::string>{"diamond", "cubic_zirconia"}));
}

TEST(Sweep, RefusesBadAxes) {
    EXPECT_THROW(parseSweepAxis("pavilion"), Error);
    EXPECT_THROW(parseSweepAxis("pavilion=45:37:1"), Error);  // inverted
    EXPECT_THROW(parseSweepAxis("pavilion=37:45:0"), Error);
    EXPECT_THROW(parseSweepAxis("pavilion=37:45"), Error);
    EXPECT_THROW(parseSweepAxis("pavilion=37,,45"), Error);
    EXPECT_THROW(parseSweepAxis("pavilion=a:45:1"), Error);
    EXPECT_THROW(parseSweepAxis("pavilion=0:1:1e-6"), Error);  // too many values

    SweepPlan plan = pavilionSweep("37:45:1", 1000, 1);
    EXPECT_NO_THROW(plan.validate());
    plan.axes = {parseSweepAxis("pavillion=37:45:1")};
    EXPECT_THROW(plan.validate(), Error);  // not a parameter
    plan.axes = {parseSweepAxis("pavilion=10:45:1")};
    EXPECT_THROW(plan.validate(), Error);  // below the parameter's range
    plan.axes = {parseSweepAxis("pavilion=37:45:1"), parseSweepAxis("pavilion=38,39")};
    EXPECT_THROW(plan.validate(), Error);  // twice
    plan.axes = {parseSweepAxis("pavilion=30:59:0.01"), parseSweepAxis("crown=10:59:0.01")};
    EXPECT_THROW(plan.validate(), Error);  // too many points
    plan.axes = {parseSweepAxis("material=diamond,unobtainium")};
    EXPECT_THROW(plan.validate(), Error);
    plan.shape = "round_brillant";
    EXPECT_THROW(plan.validate(), Error);
}

// A point of a sweep is an ordinary trace: a design traced alone with the point's settings gives the same
// tallies, bit for bit, whether its stone is shared with other points (the tilt axis) or not.
TEST(Sweep, PointEqualsSingleTrace) {
    SweepPlan plan = pavilionSweep("39.5,41.25", 20000, 2);
    plan.axes.push_back(parseSweepAxis("tilt=0,10"));
    plan.fixed = {{"crown", 33}};
    RunControl control;
    std::atomic<int> finished{0};
    SweepPointHooks hooks;
    hooks.onPoint = [&](size_t, const SweepPoint&) {
        ++finished;
        // Progress in photons and the viewer's rays over all points.
        EXPECT_EQ(control.total(), 4 * (plan.trace.photons + viewerUnits(plan.trace.viewer)));
    };
    const SweepResult result = runSweep(plan, control, hooks);
    ASSERT_EQ(result.points.size(), 4u);
    EXPECT_EQ(finished, 4);
    EXPECT_EQ(control.itemsDone(), 4u);
    EXPECT_EQ(control.phase(), RunPhase::Done);
    const SweepPoint& p = result.points[3];
    ASSERT_TRUE(p.ok()) << p.error;
    EXPECT_EQ(p.cut.at("pavilion"), 41.25);
    EXPECT_EQ(p.cut.at("crown"), 33);
    EXPECT_EQ(p.trace.light.tiltDeg, 10);

    const Stone stone =
        Stone::build(makeCut("round_brilliant", {{"pavilion", 41.25}, {"crown", 33}}), "alone");
    TraceSettings settings = plan.trace;
    settings.light.tiltDeg = 10;
    settings.threads = 1;
    const Scene scene(stone, settings);
    const TraceResult alone = trace(TraceBase(scene, settings));
    EXPECT_TRUE(alone.stats == p.stats);
    EXPECT_EQ(traceReport(alone, stone, settings)["totals"], p.totals);
    EXPECT_FALSE(result.points[2].stats == p.stats);  // the tilt changes the answer
}

// Under light straight down the weighted return peaks inside the usual pavilion angles and falls on both
// sides: toward the shallow fish-eye, where light leaks through the pavilion, and toward the deep nail-head
// (docs/optics.md).
TEST(Sweep, PavilionSweepPeaksBetweenFishEyeAndNailHead) {
    RunControl control;
    const SweepResult result = runSweep(pavilionSweep("36:46:1", 40000, 2), control);
    std::vector<double> w;
    for (const SweepPoint& p : result.points) {
        ASSERT_TRUE(p.ok()) << p.error;
        w.push_back(p.figure("weighted_return"));
    }
    const size_t peak = size_t(std::max_element(w.begin(), w.end()) - w.begin());
    const double peakPavilion = result.plan.axes[0].values[peak];
    EXPECT_GE(peakPavilion, 38);
    EXPECT_LE(peakPavilion, 43);
    const double sigma = result.points[peak].stderrOf("weighted_return");
    EXPECT_GT(w[peak] - w.front(), 5 * sigma);  // fish-eye side
    EXPECT_GT(w[peak] - w.back(), 5 * sigma);   // nail-head side
}

TEST(Sweep, SameBitsAtAnyThreadCount) {
    SweepPlan plan = pavilionSweep("39:42:1.5", 10000, 1);
    plan.axes.push_back(parseSweepAxis("material=diamond,cubic_zirconia"));
    RunControl one, two, five;
    const SweepResult a = runSweep(plan, one);
    plan.trace.threads = 2;
    const SweepResult b = runSweep(plan, two);
    plan.trace.threads = 5;  // fewer points than threads: the rest trace within points
    plan.axes.pop_back();
    const SweepResult c = runSweep(plan, five);
    EXPECT_EQ(withoutTiming(a), withoutTiming(b));
    EXPECT_EQ(sweepCsv(a), sweepCsv(b));
    for (size_t k = 0; k < c.points.size(); ++k) EXPECT_TRUE(c.points[k].stats == a.points[2 * k].stats);
}

TEST(Sweep, JsonAndCsvCarryEveryPointWithErrors) {
    SweepPlan plan = pavilionSweep("40,41", 5000, 1);
    RunControl control;
    const SweepResult result = runSweep(plan, control);
    const nlohmann::json j = sweepToJson(result);
    EXPECT_EQ(j["axes"][0]["unit"], "deg");
    EXPECT_EQ(j["points"].size(), 2u);
    EXPECT_EQ(j["points"][1]["values"]["pavilion"], 41.0);
    EXPECT_GT(j["points"][1]["totals"]["weighted_return_stderr"].get<double>(), 0);
    EXPECT_FALSE(j["fixed"].contains("pavilion"));
    EXPECT_EQ(j["fixed"]["crown"], 34.0);
    const std::string csv = sweepCsv(result);
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 3);
    EXPECT_EQ(csv.rfind("pavilion,crown_height_pct,", 0), 0u);
    EXPECT_NE(csv.find("weighted_return_stderr"), std::string::npos);
}

TEST(Sweep, CancelStopsIt) {
    RunControl control;
    control.cancel();
    EXPECT_THROW(runSweep(pavilionSweep("36:46:1", 1000, 1), control), Canceled);
    // Asked while it runs: no point after the one that asked is finished.
    RunControl running;
    int finished = 0;
    SweepPointHooks hooks;
    hooks.onPoint = [&](size_t, const SweepPoint&) {
        ++finished;
        running.cancel();
    };
    EXPECT_THROW(runSweep(pavilionSweep("36:46:1", 1000, 1), running, hooks), Canceled);
    EXPECT_EQ(finished, 1);
}

// A sweep resumed from some of its points (as the service keeps them) traces only the others and ends with
// the same sweep.json points as one that ran whole.
TEST(Sweep, ResumedFromKeptPointsGivesTheSameBits) {
    const SweepPlan plan = pavilionSweep("38:42:1", 5000, 2);
    RunControl whole;
    std::vector<nlohmann::json> kept(plan.pointCount());
    SweepPointHooks keep;
    keep.onPoint = [&](size_t k, const SweepPoint& p) { kept[k] = sweepPointJson(plan, p); };
    const nlohmann::json expected = sweepToJson(runSweep(plan, whole, keep))["points"];

    RunControl resumed;
    const auto [result, traced] = resumeSweep(plan, resumed, kept, [](size_t k) { return k % 2 == 0; });
    EXPECT_EQ(traced, (std::vector<size_t>{1, 3}));
    EXPECT_EQ(resumed.itemsDone(), 5u);
    EXPECT_EQ(sweepToJson(result)["points"].dump(), expected.dump());

    SweepPoint other = sweepPoints(plan)[1];
    EXPECT_THROW(restoreSweepPoint(plan, kept[0], other), Error);  // a point of another place in the grid
}

// With fire on, every point carries the fire figures of a single fire trace of its design, bit for bit, in
// sweep.json and sweep.csv; a sweep resumed from kept points gives the same bits, and a point kept without
// them (by a build that reported none) is traced again. With fire off, none of it appears.
TEST(Sweep, FireFiguresAtEveryPointAndResumed) {
    SweepPlan plan = pavilionSweep("39,40.5,42", 3000, 2);
    plan.trace.fire.enabled = true;
    RunControl whole;
    std::vector<nlohmann::json> kept(plan.pointCount());
    SweepPointHooks keep;
    keep.onPoint = [&](size_t k, const SweepPoint& p) { kept[k] = sweepPointJson(plan, p); };
    const SweepResult result = runSweep(plan, whole, keep);
    const nlohmann::json j = sweepToJson(result);
    const std::vector<std::string> figures = j["figures"];
    EXPECT_EQ(figures, sweepFigureNames(plan.trace, false));
    // The viewer's, the plain figures, then the fire ones: all but the colour view's.
    EXPECT_EQ(figures.size(), sweepFigureNames().size() - sweepColourFigureNames().size());
    for (const nlohmann::json& point : j["points"])
        for (const std::string& f : sweepFireFigureNames()) {
            EXPECT_TRUE(point["fire"][f].is_number()) << f;
            EXPECT_TRUE(point["fire"][f + "_stderr"].is_number()) << f;
        }
    const std::string csv = sweepCsv(result);
    EXPECT_NE(csv.find(",coloured_share,coloured_share_stderr,"), std::string::npos) << csv.substr(0, 400);

    const SweepPoint& p = result.points[1];
    const Stone stone = Stone::build(makeCut("round_brilliant", {{"pavilion", 40.5}}), "alone");
    TraceSettings settings = plan.trace;
    settings.threads = 1;
    const Scene scene(stone, settings);
    const TraceResult alone = trace(TraceBase(scene, settings));
    ASSERT_TRUE(alone.fire);
    const nlohmann::json fire = traceReport(alone, stone, settings).at("fire");
    for (const std::string& f : sweepFireFigureNames()) {
        EXPECT_EQ(p.figure(f), fire[f].get<double>()) << f;
        EXPECT_EQ(p.stderrOf(f), fire[f + "_stderr"].get<double>()) << f;
    }
    EXPECT_GT(p.figure("coloured_share"), 0);
    EXPECT_GT(p.figure("mean_separation_deg"), 0);

    kept[0].erase("fire");  // kept by a build without fire figures
    RunControl resumed;
    const auto [again, traced] = resumeSweep(plan, resumed, kept, [](size_t k) { return k != 1; });
    EXPECT_EQ(traced, (std::vector<size_t>{0, 1}));
    EXPECT_EQ(sweepToJson(again)["points"].dump(), j["points"].dump());
    EXPECT_EQ(sweepCsv(again), csv);

    plan.trace.fire.enabled = false;
    RunControl plain;
    const SweepResult dark = runSweep(plan, plain);
    const nlohmann::json d = sweepToJson(dark);
    EXPECT_FALSE(d["points"][0].contains("fire"));
    EXPECT_EQ(d["figures"], nlohmann::json(sweepFigureNames(plan.trace, false)));
    EXPECT_EQ(d["figures"].size(),
              sweepFigureNames().size() - sweepFireFigureNames().size() - sweepColourFigureNames().size());
    EXPECT_EQ(sweepCsv(dark).find("coloured"), std::string::npos);
}

TEST(Sweep, FireFiguresNeedTheFireTrace) {
    TraceSettings trace;
    EXPECT_NO_THROW(checkSweepFigure("weighted_return", trace, false));
    try {
        checkSweepFigure("coloured_share", trace, false);
        ADD_FAILURE() << "a fire figure without fire";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--fire"), std::string::npos) << e.what();
    }
    EXPECT_THROW(checkSweepFigure("sparkle", trace, false), Error);
    trace.fire.enabled = true;
    EXPECT_NO_THROW(checkSweepFigure("coloured_share", trace, false));
}
