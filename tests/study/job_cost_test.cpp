// A job's estimated cost: every part grows with the settings that multiply it, the costliest part is named
// with the field to lower, and the calibration is quick and close to what a job really takes.
#include <chrono>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include "cuts/cut_library.h"
#include "study/cost_calibration.h"
#include "study/job_cost.h"
#include "viewer/viewer_figures.h"

namespace facetlight {
namespace {

// Made-up rates (one microsecond of every kind of work): the tests of the estimate do not time anything.
CostRates unitRates() {
    CostRates r;
    r.tracePhoton = r.fireTracePhoton = r.viewerUnit = r.mapPhoton = 1e-6;
    r.renderRay = r.fireRay = r.asetRay = r.framePixel = 1e-6;
    r.jobFiles = 1e-3;
    return r;
}

StudySettings everyPart() {
    StudySettings s;
    s.render = RenderSettings{};
    s.aset = AsetSettings{};
    s.tiltSeries = TiltSeriesSettings{};
    s.firePicture = FirePictureSettings{};
    return s;
}

double partSeconds(const JobCost& cost, const std::string& name) {
    for (const CostPart& p : cost.parts)
        if (p.name == name) return p.seconds;
    ADD_FAILURE() << "no part " << name;
    return 0;
}

TEST(JobCost, EveryPartGrowsWithTheSettingsThatMultiplyIt) {
    const CostRates rates = unitRates();
    const StudySettings base = everyPart();
    const JobCost before = estimateJobCost(base, rates, 2);
    ASSERT_EQ(before.parts.size(), 8u);
    double sum = 0;
    for (const CostPart& p : before.parts) {
        EXPECT_GT(p.seconds, 0) << p.name;
        sum += p.seconds;
    }
    EXPECT_NEAR(before.seconds, sum, 1e-9 * sum);

    const std::vector<std::pair<std::string, std::function<void(StudySettings&)>>> changes = {
        {"trace", [](StudySettings& s) { s.trace.photons *= 2; }},
        {"trace", [](StudySettings& s) { s.trace.fire.enabled = true; }},
        {"viewer", [](StudySettings& s) { s.trace.viewer.office.points *= 2; }},
        {"viewer", [](StudySettings& s) { s.trace.viewer.tilts += 2; }},
        {"photon map", [](StudySettings& s) { s.render->mapPhotons *= 2; }},
        {"render", [](StudySettings& s) { s.render->width *= 2; }},
        {"render", [](StudySettings& s) { s.render->height *= 2; }},
        {"render", [](StudySettings& s) { s.render->samples *= 2; }},
        {"render", [](StudySettings& s) { s.render->maxDepth *= 2; }},
        {"fire picture", [](StudySettings& s) { s.firePicture->wavelengths *= 2; }},
        {"fire picture", [](StudySettings& s) { s.render->maxDepth *= 2; }},
        {"ASET view", [](StudySettings& s) { s.aset->samples *= 2; }},
        {"tilt series", [](StudySettings& s) { s.tiltSeries->stepDeg /= 2; }},
        {"tilt series", [](StudySettings& s) { s.tiltSeries->maxDeg *= 2; }},
        {"tilt series", [](StudySettings& s) { s.aset->samples *= 2; }},
    };
    CostRates fireRates = rates;
    fireRates.fireTracePhoton = 4 * rates.tracePhoton;
    for (const auto& [part, change] : changes) {
        StudySettings more = base;
        change(more);
        const JobCost after = estimateJobCost(more, fireRates, 2);
        EXPECT_GT(partSeconds(after, part), partSeconds(before, part)) << part;
        EXPECT_GT(after.seconds, before.seconds) << part;
    }
    // A map photon costs more in a larger map (its tree's build, n log n), never less in a smaller one.
    StudySettings map = base;
    map.render->mapPhotons = 100 * kCalibrationMapPhotons;
    const double larger = partSeconds(estimateJobCost(map, rates, 2), "photon map");
    EXPECT_GT(larger, 100 * partSeconds(estimateJobCost(
                                            [&] {
                                                StudySettings at = base;
                                                at.render->mapPhotons = kCalibrationMapPhotons;
                                                return at;
                                            }(),
                                            rates, 2),
                                        "photon map"));
    map.render->mapPhotons = 1000;
    EXPECT_DOUBLE_EQ(partSeconds(estimateJobCost(map, rates, 2), "photon map"),
                     1000 * 1e-6 * kCostSafetyFactor / 2);

    // More threads share the work (the tilt frames' encoding excepted), fewer take longer.
    EXPECT_LT(estimateJobCost(base, rates, 4).seconds, before.seconds);
    EXPECT_GT(estimateJobCost(base, rates, 1).seconds, before.seconds);
    EXPECT_DOUBLE_EQ(partSeconds(estimateJobCost(base, rates, 4), "render"),
                     partSeconds(before, "render") / 2);
}

TEST(JobCost, AJobWithoutPicturesIsItsTraceAndItsFiles) {
    StudySettings s;
    s.trace.photons = 10'000;
    s.trace.viewer.enabled = false;
    const JobCost cost = estimateJobCost(s, unitRates(), 1);
    ASSERT_EQ(cost.parts.size(), 2u);
    EXPECT_EQ(cost.largest().name, "trace");
    EXPECT_EQ(cost.parts[1].name, "files");
    EXPECT_DOUBLE_EQ(cost.seconds, (10'000 * 1e-6 + 1e-3) * kCostSafetyFactor);
}

TEST(JobCost, PolarisedAndDoublyRefractingTracesCostTheirMeasuredFactors) {
    // The calibration traces polarised (the default), and an unpolarised trace takes about as long.
    StudySettings s;
    s.trace.photons = 10'000;
    ASSERT_EQ(s.trace.polarization, PolarizationMode::On);
    const double polarised = partSeconds(estimateJobCost(s, unitRates(), 1), "trace");
    s.trace.polarization = PolarizationMode::Off;
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "trace") / polarised, 1, 1e-9);
    s.trace.material = "sapphire";  // traced at n_o alone when unpolarised
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "trace") / polarised, 1, 1e-9);
    s.trace.polarization = PolarizationMode::On;
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "trace") / polarised, 5, 1e-9);
    s.trace.constantIndex = 1.77;  // one index: no double refraction
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "trace") / polarised, 1, 1e-9);
    s.trace.constantIndex.reset();  // a job's own uniaxial material splits as a named one does
    s.trace.material = "auto";
    s.trace.customMaterial = readMaterialDefinition({{"n_o", 1.644}, {"n_e", 1.624}}, "custom_material");
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "trace") / polarised, 5, 1e-9);
    // A biaxial stone splits too, solving a quartic at each facet.
    s.trace.customMaterial.reset();
    s.trace.material = "topaz";
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "trace") / polarised, 20, 1e-9);
    s.trace.polarization = PolarizationMode::Off;  // beta alone
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "trace") / polarised, 1, 1e-9);

    // The viewer's rays go one at a time and split at 2.5x (uniaxial) and 5x (biaxial) diamond's, not at the
    // packet trace's 5x and 20x (measured: job_cost.cpp).
    s.trace.polarization = PolarizationMode::On;
    s.trace.material = "diamond";
    ASSERT_TRUE(s.trace.viewer.enabled);
    const double viewer = partSeconds(estimateJobCost(s, unitRates(), 1), "viewer");
    s.trace.material = "sapphire";
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "viewer") / viewer, 2.5, 1e-9);
    s.trace.material = "topaz";
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "viewer") / viewer, 5, 1e-9);
}

TEST(JobCost, APolariscopeCostsItsPositionsPolarised) {
    StudySettings s;
    s.trace.photons = 1000;
    s.trace.viewer.enabled = false;
    s.polariscope = PolariscopeSettings{10, 5000, 0};
    const JobCost cost = estimateJobCost(s, unitRates(), 1);
    EXPECT_EQ(cost.largest().name, "polariscope");
    EXPECT_NEAR(partSeconds(cost, "polariscope"), 10 * 5000 * 1e-6 * kCostSafetyFactor, 1e-9);
    s.polariscope->photons = 200'000;
    EXPECT_EQ(estimateJobCost(s, unitRates(), 1).largest().field, "polariscope.photons");
}

TEST(JobCost, TheDoublingCostsThreeViewRaysAPixel) {
    StudySettings s;
    s.trace.photons = 1000;
    s.trace.viewer.enabled = false;
    s.doubling = DoublingSettings{2000};
    const JobCost cost = estimateJobCost(s, unitRates(), 1);
    EXPECT_EQ(cost.largest().name, "doubling");
    EXPECT_EQ(cost.largest().field, "doubling.picture_size");
    EXPECT_NEAR(partSeconds(cost, "doubling"), 3 * 2000.0 * 2000.0 * 1e-6 * kCostSafetyFactor, 1e-9);
}

TEST(JobCost, TheColourViewCostsItsRaysAPixel) {
    StudySettings s;
    s.trace.photons = 1000;
    s.trace.viewer.enabled = false;
    s.colour = ColourSettings{1000, 8, 20};
    const JobCost cost = estimateJobCost(s, unitRates(), 1);
    EXPECT_EQ(cost.largest().name, "colour");
    EXPECT_EQ(cost.largest().field, "colour.picture_size");
    EXPECT_NEAR(partSeconds(cost, "colour"), 1000.0 * 1000.0 * 8 * 20 * 1e-6 * kCostSafetyFactor, 1e-9);

    // A sweep sees every point in colour.
    s.sweep = SweepRequest{};
    s.sweep->axes = {parseSweepAxis("size_mm=3:12:1")};
    const JobCost sweep = estimateJobCost(s, unitRates(), 1);
    EXPECT_NEAR(partSeconds(sweep, "colour"), 10 * 1000.0 * 1000.0 * 8 * 20 * 1e-6 * kCostSafetyFactor, 1e-9);

    // Traced polarised, a doubly refracting stone's view rays split at every facet: a uniaxial stone's
    // at 2.5x, a biaxial one's at 5x, as the viewer's (measured: job_cost.cpp); unpolarised, as a clear
    // stone's.
    s.sweep.reset();
    const double plain = partSeconds(estimateJobCost(s, unitRates(), 1), "colour");
    s.trace.material = "blue_sapphire";
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "colour") / plain, 2.5, 1e-9);
    s.trace.material = "zoisite";
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "colour") / plain, 5, 1e-9);
    s.trace.polarization = PolarizationMode::Off;
    EXPECT_NEAR(partSeconds(estimateJobCost(s, unitRates(), 1), "colour") / plain, 1, 1e-9);
}

// The detail of a refused job names its largest part, its size and the field that makes it large.
TEST(JobCost, TheLargestPartIsNamedWithItsSizeAndField) {
    const CostRates rates = unitRates();
    struct Case {
        std::function<void(StudySettings&)> change;
        std::string part, field, size;
    };
    const std::vector<Case> cases = {
        {[](StudySettings& s) { s.trace.photons = 100'000'000; }, "trace", "photons", "1e+08 photons"},
        {[](StudySettings& s) {
             s.render->width = s.render->height = 2048;
             s.render->samples = 256;
             s.render->maxDepth = 64;
         },
         "render", "render.samples", "2048x2048 pixels x 256 samples x depth 64"},
        {[](StudySettings& s) {
             s.render->width = 2048;
             s.render->height = 1600;
             s.firePicture.reset();
             s.tiltSeries.reset();
         },
         "render", "render.width", "2048x1600 pixels x 4 samples x depth 12"},
        {[](StudySettings& s) { s.render->mapPhotons = 100'000'000; }, "photon map", "render.map_photons",
         "1e+08 map photons"},
        {[](StudySettings& s) { s.firePicture->wavelengths = 256; }, "fire picture",
         "fire_picture.wavelengths", "400x400 pixels x 256 wavelengths x depth 12"},
        {[](StudySettings& s) {
             s.tiltSeries->maxDeg = 20;
             s.tiltSeries->stepDeg = 0.25;
         },
         "tilt series", "tilt_series.step_deg", "161 frames x 400x400 pixels x 8 view rays"},
        {[](StudySettings& s) { s.tiltSeries->maxDeg = 45; }, "tilt series", "tilt_series.max_deg",
         "91 frames x 400x400 pixels x 8 view rays"},
        {[](StudySettings& s) {
             s.aset->samples = 64;
             s.tiltSeries.reset();
             s.firePicture.reset();
         },
         "ASET view", "aset.samples", "400x400 pixels x 64 view rays"},
        {[](StudySettings& s) { s.trace.viewer.office.points = 10'000'000; }, "viewer",
         "viewer.office.points", "1.12e+09 view rays and lamp photons"},
    };
    for (const Case& c : cases) {
        StudySettings s = everyPart();
        s.trace.photons = 1000;
        c.change(s);
        const JobCost cost = estimateJobCost(s, rates, 1);
        const CostPart& top = cost.largest();
        EXPECT_EQ(top.name, c.part) << c.size;
        EXPECT_EQ(top.field, c.field) << c.size;
        EXPECT_EQ(top.size, c.size);
    }
}

// A sweep over materials costs each point by its own material's split: diamond and topaz points average
// 1x and 20x (the job's own material, diamond, would have priced them all at 1x).
TEST(JobCost, ASweepOverMaterialsCostsEachPointByItsSplit) {
    StudySettings s;
    s.trace.viewer.enabled = false;
    s.trace.photons = 10'000;
    s.sweep = SweepRequest{};
    s.sweep->axes = {parseSweepAxis("material=diamond,topaz")};
    const double mixed = partSeconds(estimateJobCost(s, unitRates(), 1), "sweep");
    s.sweep->axes = {parseSweepAxis("material=diamond,diamond")};
    EXPECT_NEAR(mixed / partSeconds(estimateJobCost(s, unitRates(), 1), "sweep"), (1 + 20) / 2.0, 1e-9);
}

TEST(JobCost, ASweepCostsItsPointsAndItsSearchItsFinerRounds) {
    const CostRates rates = unitRates();
    StudySettings s;
    s.trace.viewer.enabled = false;
    s.trace.photons = 10'000;
    SweepRequest sweep;
    sweep.axes = {SweepAxis{"pavilion", {39, 40, 41, 42}, {}}, SweepAxis{"crown", {30, 31, 32, 33, 34}, {}}};
    s.sweep = sweep;
    JobCost cost = estimateJobCost(s, rates, 1);
    ASSERT_EQ(cost.parts.size(), 2u);
    EXPECT_EQ(cost.largest().name, "sweep");
    EXPECT_EQ(cost.largest().field, "sweep.axes");
    EXPECT_EQ(cost.largest().size, "20 points x 10000 photons");
    EXPECT_DOUBLE_EQ(cost.seconds, (20 * 10'000 * 1e-6 + 1e-3) * kCostSafetyFactor);

    // Few points of many photons: the photons are what to lower.
    s.trace.photons = 50'000'000;
    s.sweep->axes[1].values = {30};
    EXPECT_EQ(estimateJobCost(s, rates, 1).largest().field, "photons");

    // The search: 3 rounds of at most 5 x 1 points at 4, 16 and 64 times the photons.
    s.trace.photons = 10'000;
    s.sweep->maximize = "brightness";
    cost = estimateJobCost(s, rates, 1);
    ASSERT_EQ(cost.parts.size(), 3u);
    EXPECT_EQ(cost.largest().name, "search");
    EXPECT_EQ(cost.largest().size, "3 finer rounds of up to 5 points, the last at 640000 photons");
    EXPECT_DOUBLE_EQ(cost.largest().seconds, 5 * (4 + 16 + 64) * 10'000 * 1e-6 * kCostSafetyFactor);
    // Its rounds at their default, its photons far below theirs: the rounds are what to lower.
    EXPECT_EQ(cost.largest().field, "sweep.refine_rounds");
    s.sweep->refineRounds = 4;
    EXPECT_GT(estimateJobCost(s, rates, 1).seconds, cost.seconds);
    s.trace.photons = 10'000'000;
    EXPECT_EQ(estimateJobCost(s, rates, 1).largest().field, "photons");

    // With the viewer, its samples grow with the photons round by round (searchRoundTrace), and each round
    // traces its reference once.
    s.trace.viewer.enabled = true;
    s.trace.photons = 10'000;
    s.sweep->refineRounds = 3;
    const double units = double(viewerUnits(s.trace.viewer));
    cost = estimateJobCost(s, rates, 1);
    ASSERT_EQ(cost.parts[1].name, "search");
    EXPECT_DOUBLE_EQ(cost.parts[1].seconds, (5 * (4 + 16 + 64) * (10'000 + units) + (4 + 16 + 64) * units) *
                                                1e-6 * kCostSafetyFactor);
}

// Measured once at the server's start: quick, every rate positive, and a real job's time within the estimate
// (which carries the safety factor) yet not far below it.
TEST(CostCalibration, IsQuickAndEstimatesARealJob) {
    const auto start = std::chrono::steady_clock::now();
    const CostRates rates = calibrateCostRates();
    const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("calibration took %.3f s\n", took);
    EXPECT_LT(took, 5.0);  // about 0.1-0.2 s; the bound leaves room for a loaded machine or a sanitizer
    for (double rate : {rates.tracePhoton, rates.fireTracePhoton, rates.viewerUnit, rates.mapPhoton,
                        rates.renderRay, rates.fireRay, rates.asetRay, rates.framePixel, rates.jobFiles}) {
        EXPECT_GT(rate, 0);
        EXPECT_TRUE(std::isfinite(rate));
    }
    EXPECT_GT(rates.fireTracePhoton, rates.tracePhoton);  // three more wavelengths a photon

    StudySettings s;
    s.trace.photons = 200'000;
    s.trace.threads = 1;
    s.trace.viewer.office.points = 1000;
    s.trace.viewer.spot.photons = 30'000;
    s.render = RenderSettings{};
    s.render->width = s.render->height = 96;
    s.render->mapPhotons = 50'000;
    s.aset = AsetSettings{};
    const Stone stone = Stone::build(makeCut("round_brilliant"), "round brilliant");
    RunControl control;
    const auto ran = std::chrono::steady_clock::now();
    runStudy(stone, s, control);
    const double real = std::chrono::duration<double>(std::chrono::steady_clock::now() - ran).count();
    const double estimate = estimateJobCost(s, rates, 1).seconds;
    std::printf("a real job took %.3f s, estimated %.3f s:", real, estimate);
    for (const CostPart& p : estimateJobCost(s, rates, 1).parts)
        std::printf(" %s %.3f s", p.name.c_str(), p.seconds);
    std::printf("\n");
    EXPECT_LT(real, estimate);
    EXPECT_GT(real, estimate / 20);
}

}  // namespace
}  // namespace facetlight
