// Absorption in the tracer (docs/optics.md, "Absorption"): a slab's transmission against Beer-Lambert with
// its Fresnel losses in closed form, doubling the size squares the single-pass transmission, pleochroism by
// the wave's angle to the optic axis, a clear spectrum changes no bit, and pinned bits of an absorbing trace.
#include <gtest/gtest.h>

#include <cmath>

#include "optics/material.h"
#include "support/fixtures.h"
#include "trace/photon_tracer.h"

namespace facetlight {
namespace {

using nlohmann::json;

AbsorptionSpectrum flat(double alphaO, std::optional<double> alphaE = std::nullopt) {
    AbsorptionSpectrum a{{400, 700}, {alphaO, alphaO}, {}};
    if (alphaE) a.extraordinaryPerMm = {*alphaE, *alphaE};
    return a;
}

// Light straight down onto the unit cube's top: a slab at normal incidence, 1 mesh unit thick.
TraceSettings slab(uint64_t photons) {
    TraceSettings s;
    s.photons = photons;
    s.seed = 11;
    s.threads = 2;
    s.dispersion = false;
    return s;
}

double thicknessMm(const Stone& cube, const TraceSettings& s) {
    return s.sizeMm / Scene(cube, s).diameter();
}

void expectBalanced(const FacetStats& s) {
    EXPECT_EQ(s.hit, s.entered + s.reflectedAtEntry);
    EXPECT_EQ(s.entered, s.exited + s.trapped + s.absorbed);
}

// The shares of the light that hits a slab of reflectance R per face and single-pass transmission tau
// (docs/optics.md, "Absorption"): through the bottom, back out of the top (first-surface reflection
// included) and absorbed, summed over every internal reflection.
struct SlabShares {
    double down, up, absorbed;
};
SlabShares slabShares(double R, double tau) {
    const double through = (1 - R) * (1 - R) * tau / (1 - R * R * tau * tau);
    const double back = R + (1 - R) * (1 - R) * R * tau * tau / (1 - R * R * tau * tau);
    return {through, back, (1 - R) * (1 - tau) / (1 - R * tau)};
}

double reflectance(double n) {
    return (n - 1) * (n - 1) / ((n + 1) * (n + 1));
}

// The measured shares of a slab trace, per photon that hit it.
SlabShares measured(const Stone& cube, const FacetStats& s) {
    uint64_t down = 0, up = s.reflectedAtEntry;
    for (const Facet& f : cube.facets) {
        if (f.normal.z < -0.999) down += s.facets[f.id].leaving;
        if (f.normal.z > 0.999) up += s.facets[f.id].leaving;
    }
    const double n = double(s.hit);
    return {double(down) / n, double(up) / n, double(s.absorbed) / n};
}

void expectNear(double measured, double expected, uint64_t n, const char* what) {
    const double se = std::sqrt(expected * (1 - expected) / double(n));
    EXPECT_NEAR(measured, expected, 4 * se) << what;
}

TEST(AbsorbingTrace, SlabTransmitsBeerLambertWithItsFresnelLosses) {
    const Stone cube = test::unitCube();
    TraceSettings s = slab(400'000);
    const double d = thicknessMm(cube, s);
    const double alpha = std::log(2.0) / d;  // half is left after one pass
    s.absorption = flat(alpha);
    const TraceResult r = test::traceStone(cube, s);
    expectBalanced(r.stats);
    const double R = reflectance(Material::byName("diamond").indexD());
    const SlabShares want = slabShares(R, std::exp(-alpha * d)), got = measured(cube, r.stats);
    EXPECT_NEAR(want.down + want.up + want.absorbed, 1, 1e-12);
    expectNear(got.down, want.down, r.stats.hit, "through");
    expectNear(got.up, want.up, r.stats.hit, "back");
    expectNear(got.absorbed, want.absorbed, r.stats.hit, "absorbed");
    EXPECT_EQ(r.stats.trapped, 0u);
    // The report: absorbed and its share with the share's standard error.
    const json totals = traceReport(r, cube, s)["totals"];
    EXPECT_EQ(totals["absorbed"].get<uint64_t>(), r.stats.absorbed);
    EXPECT_DOUBLE_EQ(totals["absorbed_share"].get<double>(), got.absorbed);
    EXPECT_NEAR(totals["absorbed_share_stderr"].get<double>(),
                std::sqrt(got.absorbed * (1 - got.absorbed) / double(r.stats.hit)), 1e-12);
}

// Single-pass transmission from a slab's measured transmission T: the root in (0, 1] of
// T R^2 tau^2 + (1 - R)^2 tau - T = 0.
double singlePass(double T, double R) {
    const double a = T * R * R, b = (1 - R) * (1 - R);
    return (-b + std::sqrt(b * b + 4 * a * T)) / (2 * a);
}

TEST(AbsorbingTrace, DoublingTheSizeSquaresTheSinglePassTransmission) {
    const Stone cube = test::unitCube();
    const double R = reflectance(Material::byName("diamond").indexD());
    TraceSettings s = slab(400'000);
    s.absorption = flat(0.1);
    std::array<double, 2> tau{}, se{};
    for (int k = 0; k < 2; ++k) {
        s.sizeMm = k == 0 ? 5 : 10;
        const TraceResult r = test::traceStone(cube, s);
        expectBalanced(r.stats);
        const double T = measured(cube, r.stats).down;
        tau[k] = singlePass(T, R);
        // The binomial error of T carried through singlePass().
        const double h = 1e-6, slope = (singlePass(T + h, R) - singlePass(T - h, R)) / (2 * h);
        se[k] = slope * std::sqrt(T * (1 - T) / double(r.stats.hit));
    }
    EXPECT_NEAR(tau[0], std::exp(-0.1 * 5), 4 * se[0]);
    EXPECT_NEAR(tau[1], tau[0] * tau[0], 4 * std::hypot(se[1], 2 * tau[0] * se[0]));
}

// Sapphire absorbing only the extraordinary wave (alpha_o 0): light along the optic axis crosses clear;
// across it, the half of the light that travels as the extraordinary wave meets alpha_e; unpolarised tracing
// absorbs the mixture 2/3 alpha_o + 1/3 alpha_e.
TEST(AbsorbingTrace, PleochroismFollowsTheWaveAndTheAxis) {
    const Stone cube = test::unitCube();
    TraceSettings s = slab(200'000);
    s.material = "sapphire";
    s.absorption = flat(0, 0.2);
    const double d = thicknessMm(cube, s), tauE = std::exp(-0.2 * d);
    const std::array<double, 3> n = Material::byName("sapphire").principalIndices(Material::kSodiumD);

    s.polarization = PolarizationMode::On;
    s.opticAxis = {0, 0};  // along the light
    const TraceResult along = test::traceStone(cube, s);
    expectBalanced(along.stats);
    EXPECT_EQ(along.stats.absorbed, 0u);
    EXPECT_GT(along.stats.exited, along.stats.hit / 2);

    s.opticAxis = {90, 0};  // across it: theta 90 deg, the e-wave at n_e
    const TraceResult across = test::traceStone(cube, s);
    expectBalanced(across.stats);
    const double Re = reflectance(n[2]);
    expectNear(measured(cube, across.stats).absorbed, 0.5 * (1 - Re) * (1 - tauE) / (1 - Re * tauE),
               across.stats.hit, "e-wave absorbed");

    s.polarization = PolarizationMode::Off;
    const TraceResult mixed = test::traceStone(cube, s);
    expectBalanced(mixed.stats);
    const double tauMix = std::exp(-0.2 / 3 * d), Ro = reflectance(n[0]);
    expectNear(measured(cube, mixed.stats).absorbed, (1 - Ro) * (1 - tauMix) / (1 - Ro * tauMix),
               mixed.stats.hit, "o/e mixture absorbed");
}

// Topaz absorbing by one of its rays: light down the stone's z meets waves whose fields lie along the two
// principal axes across z, each half of the unpolarised light; the one along the absorbing ray's axis
// absorbs as a slab of that alpha at its own index, the other crosses clear. Tilted, the axes change places;
// unpolarised tracing takes the rays' mean.
TEST(AbsorbingTrace, TrichroismFollowsTheWavesField) {
    const Stone cube = test::unitCube();
    TraceSettings s = slab(100'000);
    s.material = "topaz";
    s.polarization = PolarizationMode::On;
    const double d = thicknessMm(cube, s), tau = std::exp(-0.2 * d);
    const std::array<double, 3> n = Material::byName("topaz").principalIndices(Material::kSodiumD);
    const auto ray = [](int axis) {
        AbsorptionSpectrum a{{400, 700}, {}, {}};
        for (int k = 0; k < 3; ++k) a.rayPerMm[size_t(k)] = {k == axis ? 0.2 : 0.0, k == axis ? 0.2 : 0.0};
        a.ordinaryPerMm = AbsorptionSpectrum::meanOfRays(a.rayPerMm);
        return a;
    };
    const auto halfAbsorbed = [&](double index) {
        const double R = reflectance(index);
        return 0.5 * (1 - R) * (1 - tau) / (1 - R * tau);
    };
    // X, Y, Z along the stone's x, y, z: the waves' fields along x (index alpha) and y (beta).
    s.absorption = ray(0);
    TraceResult r = test::traceStone(cube, s);
    expectBalanced(r.stats);
    expectNear(measured(cube, r.stats).absorbed, halfAbsorbed(n[0]), r.stats.hit, "X ray absorbed");
    s.absorption = ray(1);
    r = test::traceStone(cube, s);
    expectNear(measured(cube, r.stats).absorbed, halfAbsorbed(n[1]), r.stats.hit, "Y ray absorbed");
    s.absorption = ray(2);
    r = test::traceStone(cube, s);
    EXPECT_EQ(r.stats.absorbed, 0u) << "no field along Z";
    // Tilted 90 deg toward x: X points down the light, Z along x, so the X ray is dark no more and Z shows.
    s.opticAxis.tiltDeg = 90;
    s.absorption = ray(0);
    EXPECT_EQ(test::traceStone(cube, s).stats.absorbed, 0u) << "no field along X";
    s.absorption = ray(2);
    r = test::traceStone(cube, s);
    expectNear(measured(cube, r.stats).absorbed, halfAbsorbed(n[2]), r.stats.hit, "Z ray absorbed");
    // Unpolarised: one index (beta) and the rays' mean.
    s.polarization = PolarizationMode::Off;
    r = test::traceStone(cube, s);
    const double tauMean = std::exp(-0.2 / 3 * d), Rb = reflectance(n[1]);
    expectNear(measured(cube, r.stats).absorbed, (1 - Rb) * (1 - tauMean) / (1 - Rb * tauMean), r.stats.hit,
               "the rays' mean absorbed");
}

// A spectrum of zeros is no absorption: no draw is added, so every tally has today's bits.
TEST(AbsorbingTrace, AClearSpectrumChangesNoBit) {
    const Stone& stone = test::roundBrilliant();
    for (PolarizationMode polarization : {PolarizationMode::Off, PolarizationMode::On}) {
        TraceSettings s;
        s.photons = 30'000;
        s.threads = 2;
        s.material = "tourmaline";
        s.light.model = LightModelKind::Hemisphere;
        s.polarization = polarization;
        const TraceResult clear = test::traceStone(stone, s);
        s.absorption = flat(0, 0);
        const TraceResult zero = test::traceStone(stone, s);
        EXPECT_TRUE(zero.stats == clear.stats);
        EXPECT_EQ(zero.stats.absorbed, 0u);
    }
}

// An absorbing trace's bits, pinned, unpolarised and polarised: a change to the walk, the draws or the tallies
// shows here. The same for any thread count.
TEST(AbsorbingTrace, PinnedBits) {
    const Stone& stone = test::roundBrilliant();
    const struct {
        PolarizationMode mode;
        uint64_t exited, absorbed, crownReturn, weightSum;
    } pins[] = {{PolarizationMode::Off, 3148, 6112, 2003, 1508724590447u},
                {PolarizationMode::On, 3163, 6097, 1999, 1504300663063u}};
    for (const auto& pin : pins) {
        TraceSettings s;
        s.photons = 20'000;
        s.seed = 29;
        s.polarization = pin.mode;
        s.light.model = LightModelKind::Hemisphere;
        s.absorption = AbsorptionSpectrum{{400, 550, 700}, {0.2, 0.05, 0.1}, {}};
        FacetStats first;
        for (int threads : {1, 3}) {
            s.threads = threads;
            const TraceResult r = test::traceStone(stone, s);
            expectBalanced(r.stats);
            if (threads == 1) {
                first = r.stats;
            } else {
                EXPECT_TRUE(r.stats == first);
            }
        }
        const std::string mode(kPolarizationNames.name(pin.mode));
        EXPECT_EQ(first.hit, 11775u) << mode;
        EXPECT_EQ(first.entered, 9260u) << mode;
        EXPECT_EQ(first.exited, pin.exited) << mode;
        EXPECT_EQ(first.absorbed, pin.absorbed) << mode;
        EXPECT_EQ(first.trapped, 0u) << mode;
        EXPECT_EQ(first.crownReturn, pin.crownReturn) << mode;
        EXPECT_EQ(first.weightSum, pin.weightSum) << mode;
    }
}

}  // namespace
}  // namespace facetlight
