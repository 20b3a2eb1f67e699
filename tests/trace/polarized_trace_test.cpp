// The tracer with polarised photons (docs/optics.md, "Polarisation"): analytic averages of whole traces.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

#include "optics/material.h"
#include "support/expect_error.h"
#include "support/fixtures.h"
#include "trace/photon_walker.h"
#include "viewer/verdict.h"

using namespace facetlight;
using nlohmann::json;

namespace {

uint32_t facetFacing(const Stone& stone, const Vec3& n) {
    for (const Facet& f : stone.facets)
        if (dot(f.normal, n) > 0.999) return f.id;
    throw Error("no such facet");
}

TraceSettings polarized(uint64_t photons) {
    TraceSettings s;
    s.photons = photons;
    s.seed = 11;
    s.dispersion = false;
    s.polarization = PolarizationMode::On;
    return s;
}

// What crossed and parallel analysers below the stone pass of the light that leaves through its bottom.
struct AnalyserTally {
    Vec3f crossed, parallel;
    uint32_t bottom;
    double crossedSum = 0, parallelSum = 0;
    uint64_t through = 0;
    Polarization last;
    Vec3f lastDir;

    void wavelength(float) {}
    void missed() {}
    void reflectedAtEntry(uint32_t, const Vec3f&, const Vec3f&) {}
    void entered(uint32_t) {}
    void internalReflection(uint32_t) {}
    void exitPolarization(const Polarization& p, const Vec3f& d) { last = p, lastDir = d; }
    void exited(uint32_t facet, const Vec3f&, const Vec3f&, uint32_t) {
        if (facet != bottom) return;
        ++through;
        crossedSum += analyserShare(last, lastDir, crossed);
        parallelSum += analyserShare(last, lastDir, parallel);
    }
    void trapped(uint32_t) {}
    void lost(uint32_t) {}
    void absorbed(uint32_t) {}
};

// The brilliant's report with `settings` at 1, 2 and 3 threads, which must agree bit for bit (timing and the
// thread count apart), photons conserved in each: the first.
json sameAtAnyThreadCount(TraceSettings settings) {
    json first;
    for (int threads : {1, 2, 3}) {
        settings.threads = threads;
        const TraceResult r = test::traceStone(test::roundBrilliant(), settings);
        EXPECT_EQ(r.stats.entered, r.stats.exited + r.stats.trapped);
        EXPECT_EQ(r.stats.hit, r.stats.entered + r.stats.reflectedAtEntry);
        json j = traceReport(r, test::roundBrilliant(), settings);
        j.erase("timing");
        j["settings"].erase("threads");
        if (threads == 1) {
            first = j;
        } else {
            EXPECT_EQ(j.dump(), first.dump()) << threads << " threads";
        }
    }
    return first;
}

}  // namespace

TEST(PolarizedTrace, IsotropicSlabBetweenCrossedPolarisersIsDark) {
    const Stone stone = test::unitCube();
    for (double polarizer : {0.0, 30.0, 90.0}) {
        TraceSettings settings = polarized(20'000);
        settings.light.polarizerDeg = polarizer;
        const Scene scene(stone, settings);
        const TraceBase trace(scene, settings);
        const double a = radians(polarizer);
        const Vec3f along(float(std::cos(a)), float(std::sin(a)), 0);
        AnalyserTally t{{-along.y, along.x, 0}, along, facetFacing(stone, {0, 0, -1}), 0, 0, 0, {}, {}};
        for (uint64_t i = 0; i < settings.photons; ++i) PhotonWalker::walk(trace, *scene.convex(), i, t);
        ASSERT_GT(t.through, settings.photons / 3);
        // Straight through at normal incidence the light keeps its polarisation (Born & Wolf, sec. 1.5.2).
        EXPECT_LT(t.crossedSum, 1e-7 * double(t.through)) << polarizer << " (float rounding only)";
        EXPECT_NEAR(t.parallelSum, double(t.through), 1e-4 * double(t.through)) << polarizer;
    }
}

TEST(PolarizedTrace, AtBrewstersAngleOnlySLightReflects) {
    // Collimated light at Brewster's angle on a diamond cube's top, in the x-z plane: a polariser along x
    // lets through p light (in the plane of incidence), one along y s light (Born & Wolf, sec. 1.5.3).
    const Stone stone = test::unitCube();
    const double n = Material::byName("diamond").indexD();
    const double brewster = std::atan(n);
    const double thetaT = std::asin(std::sin(brewster) / n);
    const double rs = std::sin(brewster - thetaT) / std::sin(brewster + thetaT), Rs = rs * rs;
    const uint32_t top = facetFacing(stone, {0, 0, 1});
    struct Case {
        std::optional<double> polarizer;
        double expected;
    };
    for (const Case& c : {Case{0.0, 0.0}, Case{90.0, Rs}, Case{std::nullopt, Rs / 2}}) {
        TraceSettings settings = polarized(100'000);
        settings.threads = 2;
        settings.light.direction = {std::sin(brewster), 0, -std::cos(brewster)};
        settings.light.polarizerDeg = c.polarizer;
        const FacetStats s = test::traceStone(stone, settings).stats;
        const double met = double(s.facets[top].reflected + s.facets[top].entering);
        ASSERT_GT(met, 10'000);
        const double reflected = double(s.facets[top].reflected) / met;
        EXPECT_NEAR(reflected, c.expected, 4 * std::sqrt(Rs * (1 - Rs) / met) + 1e-6)
            << (c.polarizer ? std::to_string(*c.polarizer) : "unpolarised");
        if (c.expected == 0) {
            EXPECT_EQ(s.facets[top].reflected, 0u);
        }
    }
}

TEST(PolarizedTrace, IdenticalForAnyThreadCount) {
    TraceSettings settings = polarized(3 * kPhotonBlock + 77);
    settings.dispersion = true;
    settings.light.model = LightModelKind::Hemisphere;
    settings.fire.enabled = true;
    const json first = sameAtAnyThreadCount(settings);
    EXPECT_EQ(first["settings"]["polarization"], "on");
}

TEST(PolarizedTrace, PolarisedAndUnpolarisedTracesDiffer) {
    // The same photons and draws: only the reflect-or-refract probabilities after the first facet differ, so
    // the two traces are close but not the same bits.
    TraceSettings settings = polarized(20'000);
    const TraceResult on = test::traceStone(test::roundBrilliant(), settings);
    settings.polarization = PolarizationMode::Off;
    const TraceResult off = test::traceStone(test::roundBrilliant(), settings);
    EXPECT_FALSE(on.stats == off.stats);
    EXPECT_EQ(on.stats.hit, off.stats.hit);
    EXPECT_NEAR(double(on.stats.exited) / double(on.stats.hit),
                double(off.stats.exited) / double(off.stats.hit), 0.02);
}

TEST(PolarizedTrace, PolariserNeedsPolarisedTracing) {
    test::expectError(
        [] {
            TraceSettings::fromJson({{"polarization", "off"}, {"light", {{"polarizer_deg", 30}}}});
        },
        "light.polarizer_deg");
    test::expectError([] { TraceSettings::fromJson({{"polarization", "partly"}}); }, "polarization");
    test::expectError(
        [] {
            TraceSettings::fromJson({{"polarization", "on"}, {"light", {{"polarizer_deg", 180}}}});
        },
        "light.polarizer_deg");
    const TraceSettings s = TraceSettings::fromJson({{"light", {{"polarizer_deg", 30}}}});  // on by default
    EXPECT_EQ(s.polarization, PolarizationMode::On);
    EXPECT_EQ(*s.light.polarizerDeg, 30);
    EXPECT_EQ(toJson(s)["light"]["polarizer_deg"], 30);
}

namespace {

// Photons of a collimated beam along -z through the point (x, y) above the stone (centred on the origin), walked one at a time by the
// tracer's own steps (PhotonWalker::enter and step).
template <class Visitor>
void shootThrough(const TraceBase& trace, const Scene& scene, float x, float y, uint64_t photons, Visitor& v) {
    for (uint64_t i = 0; i < photons; ++i) {
        PhotonWalker::Photon ph;
        ph.rng = Rng(5, i);
        ph.n = scene.fixedIndex();
        ph.nE = trace.principalIndex(2, Material::kSodiumD);
        const LightRay ray{{x, y, 3}, {0, 0, -1}};
        if (PhotonWalker::enter(trace, *scene.convex(), ray, v, ph)) {
            while (PhotonWalker::step(trace, *scene.convex(), v, ph)) {
            }
        }
    }
}

// Where light that goes straight through leaves the bottom.
struct ExitSpots : AnalyserTally {
    std::vector<Vec3f> spots;
    void exited(uint32_t facet, const Vec3f& p, const Vec3f& d, uint32_t bounces) {
        AnalyserTally::exited(facet, p, d, bounces);
        if (facet == bottom && bounces == 0) spots.push_back(p);
    }
};

TraceSettings calcite(double axisTiltDeg) {
    TraceSettings s = polarized(1);
    s.material = "calcite";
    s.opticAxis.tiltDeg = axisTiltDeg;
    return s;
}

// A calcite block with its axis `axisTiltDeg` from the top's normal lit straight down through one point, the
// light's polariser at `polarizerDeg`: what crossed and parallel analysers below it pass.
AnalyserTally betweenPolarisers(double axisTiltDeg, double polarizerDeg, uint64_t photons) {
    const Stone stone = test::unitCube();
    TraceSettings settings = calcite(axisTiltDeg);
    settings.light.polarizerDeg = polarizerDeg;
    const Scene scene(stone, settings);
    const TraceBase trace(scene, settings);
    const double a = radians(polarizerDeg);
    const Vec3f along(float(std::cos(a)), float(std::sin(a)), 0);
    AnalyserTally v{{-along.y, along.x, 0}, along, facetFacing(stone, {0, 0, -1}), 0, 0, 0, {}, {}};
    shootThrough(trace, scene, 0.1f, -0.1f, photons, v);
    return v;
}

}  // namespace

TEST(BirefringentTrace, CalciteRhombShowsTwoImagesAsFarApartAsTheWalkOff) {
    // A calcite block with its optic axis 44.6 deg from the top's normal (a cleavage rhomb's; Born & Wolf,
    // sec. 15.3.3), lit straight down through one point: the ordinary ray goes straight through, the
    // extraordinary one walks off by rho, tan rho = (n_o^2 - n_e^2) sin t cos t / (n_e^2 cos^2 t + n_o^2 sin^2 t)
    // (Born & Wolf eq. 15.3.(29) with the wave normal at t to the axis), so the two spots on the bottom (1 below the top)
    // lie tan(rho) apart along the axis's azimuth.
    const Stone stone = test::unitCube();
    const TraceSettings settings = calcite(44.6);
    const Scene scene(stone, settings);
    const TraceBase trace(scene, settings);
    ASSERT_TRUE(trace.birefringent());
    const std::array<double, 3> n = Material::byName("calcite").principalIndices(Material::kSodiumD);
    const double t = radians(44.6), no = n[0], ne = n[2];
    const double tanRho =
        (no * no - ne * ne) * std::sin(t) * std::cos(t) / (ne * ne * std::cos(t) * std::cos(t) + no * no * std::sin(t) * std::sin(t));
    ASSERT_NEAR(degrees(std::atan(tanRho)), 6.2, 0.1);
    ExitSpots v;
    v.crossed = {0, 1, 0}, v.parallel = {1, 0, 0}, v.bottom = facetFacing(stone, {0, 0, -1});
    shootThrough(trace, scene, -0.2f, 0.1f, 4000, v);
    uint64_t ordinary = 0, extraordinary = 0;
    for (const Vec3f& p : v.spots) {
        EXPECT_NEAR(p.y, 0.1, 1e-5);
        if (std::abs(p.x + 0.2f) < 1e-5f) {
            ++ordinary;
        } else {
            EXPECT_NEAR(p.x + 0.2, tanRho, 1e-5) << "the e ray walks off toward the axis";
            ++extraordinary;
        }
    }
    // Unpolarised light splits about evenly (each wave's entry loss is a few per cent).
    const double total = double(ordinary + extraordinary);
    ASSERT_GT(total, 3000);
    EXPECT_NEAR(double(ordinary) / total, 0.5, 0.04);
    // Light polarised across the principal plane (along y) enters as the ordinary wave only, along x as the
    // extraordinary wave only.
    for (double polarizer : {90.0, 0.0}) {
        TraceSettings polarised = settings;
        polarised.light.polarizerDeg = polarizer;
        const Scene polarisedScene(stone, polarised);
        const TraceBase withPolariser(polarisedScene, polarised);
        ExitSpots w;
        w.crossed = {0, 1, 0}, w.parallel = {1, 0, 0}, w.bottom = v.bottom;
        shootThrough(withPolariser, polarisedScene, -0.2f, 0.1f, 1000, w);
        ASSERT_GT(w.spots.size(), 700u);
        for (const Vec3f& p : w.spots)
            EXPECT_NEAR(p.x + 0.2, polarizer == 90 ? 0 : tanRho, 1e-5) << polarizer;
    }
}

TEST(BirefringentTrace, SlabCutAlongItsAxisBlinksFourTimesATurnBetweenCrossedPolarisers) {
    // A uniaxial slab with its axis in the plane of its faces (along x) between crossed polarisers, light
    // straight through: light polarised at alpha to the axis enters as e (share cos^2 alpha, polarised along
    // the axis) and o (sin^2 alpha, across it); the analyser at alpha + 90 passes sin^2 alpha of the first and
    // cos^2 alpha of the second: sin^2(2 alpha) / 2 in all, dark at 0, 90, 180 and 270 deg (Hecht, Optics,
    // sec. 8.10; the two waves' Fresnel losses differ by under 2 % for calcite).
    for (double alpha : {0.0, 22.5, 45.0, 90.0, 135.0}) {
        const AnalyserTally v = betweenPolarisers(90, alpha, 20000);
        ASSERT_GT(v.through, 15000u);
        const double expected = 0.5 * std::pow(std::sin(2 * radians(alpha)), 2);
        EXPECT_NEAR(v.crossedSum / double(v.through), expected, 0.02) << alpha;
        if (expected == 0) {
            EXPECT_LT(v.crossedSum, 1e-6 * double(v.through)) << alpha << " deg: dark";
        }
    }
}

TEST(BirefringentTrace, SapphireBrilliantIsTheSameAtAnyThreadCountAndConservesPhotons) {
    TraceSettings settings = polarized(2 * kPhotonBlock + 99);
    settings.material = "sapphire";
    settings.dispersion = true;
    settings.opticAxis = {30, 45};
    settings.light.model = LightModelKind::Hemisphere;
    settings.fire.enabled = true;
    const json first = sameAtAnyThreadCount(settings);
    EXPECT_GT(first["totals"]["crown_return"].get<double>(), 0.2);
    // The same stone traced with polarisation off sees n_o alone.
    settings.polarization = PolarizationMode::Off;
    const DesignFacts off = designFacts(test::roundBrilliant(), settings);
    EXPECT_NE(off.doubleRefraction.find("not traced"), std::string::npos);
    settings.polarization = PolarizationMode::On;
    EXPECT_NE(designFacts(test::roundBrilliant(), settings).doubleRefraction.find("traced: each ray splits"),
              std::string::npos);
}

// A biaxial stone splits every ray into its fast and slow waves (optics/birefringence.h): the same bits at
// any thread count with dispersion and the fire trace, every photon accounted for.
TEST(BiaxialTrace, TopazBrilliantIsTheSameAtAnyThreadCountAndConservesPhotons) {
    TraceSettings settings = polarized(2 * kPhotonBlock + 99);
    settings.material = "topaz";  // clear: peridot absorbs by its spectrum
    settings.dispersion = true;
    settings.opticAxis = {30, 45, 20};
    settings.light.model = LightModelKind::Hemisphere;
    settings.fire.enabled = true;
    const json first = sameAtAnyThreadCount(settings);
    EXPECT_GT(first["totals"]["crown_return"].get<double>(), 0.2);
    EXPECT_EQ(first["settings"]["optic_axis"]["rotation_deg"], 20);
    EXPECT_NE(designFacts(test::roundBrilliant(), settings).doubleRefraction.find("fast and slow"),
              std::string::npos);
    // Turning X and Y about Z changes the trace; with polarisation off it sees beta alone, as before.
    TraceSettings turned = settings;
    turned.opticAxis.rotationDeg = 110;
    turned.threads = 1;
    settings.threads = 1;
    EXPECT_FALSE(test::traceStone(test::roundBrilliant(), turned).stats ==
                 test::traceStone(test::roundBrilliant(), settings).stats);
    settings.polarization = PolarizationMode::Off;
    EXPECT_NE(designFacts(test::roundBrilliant(), settings).doubleRefraction.find("sees beta"),
              std::string::npos);
}

TEST(BiaxialTrace, AxisRotationNeedsABiaxialMaterial) {
    TraceSettings settings;
    settings.material = "sapphire";
    json j = toJson(settings);
    j["optic_axis"]["rotation_deg"] = 30;
    try {
        TraceSettings::fromJson(j);
        ADD_FAILURE() << "a uniaxial stone took a rotation";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("optic_axis.rotation_deg"), std::string::npos) << e.what();
    }
    j["material"] = "topaz";
    EXPECT_EQ(TraceSettings::fromJson(j).opticAxis.rotationDeg, 30);
    j["optic_axis"]["rotation_deg"] = 360;
    EXPECT_THROW(TraceSettings::fromJson(j), Error);
    // The principal axes: a right-handed orthonormal frame, Z the tilted axis, X at the rotation from x.
    OpticAxisSettings a{0, 70, 30};
    std::array<Vec3, 3> x = a.principalAxes();
    EXPECT_NEAR(x[0].x, std::cos(radians(30)), 1e-12);
    EXPECT_NEAR(x[0].y, std::sin(radians(30)), 1e-12);
    a = {40, 110, 25};
    x = a.principalAxes();
    EXPECT_NEAR(length(cross(x[0], x[1]) - x[2]), 0, 1e-12);
    EXPECT_NEAR(length(x[2] - a.direction()), 0, 1e-12);
}

TEST(BirefringentTrace, ViewerFiguresOfADoublyRefractingStone) {
    // The viewer's rays and the spot lamps' photons carry one index each: n_e follows from it (setIndex).
    TraceSettings settings = polarized(1000);
    settings.material = "sapphire";
    settings.dispersion = true;
    settings.viewer.office.points = 200;
    settings.viewer.spot.photons = 2000;
    const nlohmann::json v = viewerReport(test::roundBrilliant(), settings);
    EXPECT_GT(v["figures"]["brightness"]["value"].get<double>(), 0.05);
    EXPECT_GT(v["figures"]["fire"]["value"].get<double>(), 0.0);
}

TEST(BirefringentTrace, AlongTheOpticAxisTheWavesStayInPhase) {
    // A calcite block with its axis along the light: both waves see n_o and keep in step, so the block between
    // crossed polarisers stays dark at every polariser angle, as an isotropic one does.
    for (double polarizer : {0.0, 30.0, 45.0}) {
        const AnalyserTally v = betweenPolarisers(0, polarizer, 5000);
        ASSERT_GT(v.through, 4000u);
        EXPECT_LT(v.crossedSum, 1e-6 * double(v.through)) << polarizer;
    }
    // Tilted well off the light it splits again (the slab test above).
    const Stone stone = test::unitCube();
    const TraceSettings tilted = calcite(20);
    const Scene scene(stone, tilted);
    EXPECT_FALSE(TraceBase(scene, tilted).nearOpticAxis({0, 0, -1}));
    EXPECT_TRUE(TraceBase(scene, tilted).nearOpticAxis(calcite(20).opticAxis.direction()));
}
