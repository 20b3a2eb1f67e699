#include "optics/birefringence.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <utility>

#include "optics/material.h"
#include "optics/optic_axis.h"
#include "util/error.h"

namespace facetlight {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180;

Vec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return normalize(Vec3{g(rng), g(rng), g(rng)});
}

double totalShare(const InterfaceWaves& w, int basis) {
    return w.reflected[0].share[basis] + w.reflected[1].share[basis] + w.transmitted[0].share[basis] +
           w.transmitted[1].share[basis];
}

// Fresnel amplitudes from n1 to n2 at incidence i (docs/optics.md, "Polarisation"): the reference the
// isotropic limit must reproduce.
struct Fresnel {
    double rs, rp, Rs, Rp;
};
Fresnel fresnel(double n1, double n2, double i) {
    const double cosI = std::cos(i), sinT = n1 * std::sin(i) / n2, cosT = std::sqrt(1 - sinT * sinT);
    const double rs = (n1 * cosI - n2 * cosT) / (n1 * cosI + n2 * cosT);
    const double rp = (n2 * cosI - n1 * cosT) / (n2 * cosI + n1 * cosT);
    return {rs, rp, rs * rs, rp * rp};
}

// Light in the x-z plane at incidence i onto a facet of outward normal +z (from above, or from inside
// towards it).
Vec3 incoming(double i) {
    return {std::sin(i), 0, -std::cos(i)};
}

TEST(Birefringence, IsotropicCrystalFromOutsideIsFresnel) {
    std::mt19937_64 rng(1);
    for (double n : {1.5, 2.4173}) {
        const UniaxialMedium glass{n, n, randomUnit(rng)};
        for (double deg : {0.0, 10.0, 30.0, 45.0, 60.0, 75.0, 89.0}) {
            const Fresnel f = fresnel(1, n, deg * kDeg);
            const InterfaceWaves w = enterCrystal(glass, incoming(deg * kDeg), {0, 0, 1});
            ASSERT_EQ(w.incidentCount, 2);
            EXPECT_FALSE(w.totalInternalReflection());
            // s in, s out and p in, p out with Fresnel's signed amplitudes; no s <-> p coupling.
            EXPECT_NEAR(w.reflected[0].amplitude[0].real(), f.rs, 1e-12) << n << " " << deg;
            EXPECT_NEAR(w.reflected[1].amplitude[1].real(), f.rp, 1e-12) << n << " " << deg;
            EXPECT_NEAR(std::abs(w.reflected[1].amplitude[0]), 0, 1e-12);
            EXPECT_NEAR(std::abs(w.reflected[0].amplitude[1]), 0, 1e-12);
            EXPECT_NEAR(w.reflected[0].share[0], f.Rs, 1e-12);
            EXPECT_NEAR(w.reflected[1].share[1], f.Rp, 1e-12);
            EXPECT_NEAR(w.transmitted[0].share[0] + w.transmitted[1].share[0], 1 - f.Rs, 1e-12);
            EXPECT_NEAR(w.transmitted[0].share[1] + w.transmitted[1].share[1], 1 - f.Rp, 1e-12);
        }
    }
}

TEST(Birefringence, IsotropicCrystalFromInsideIsFresnel) {
    std::mt19937_64 rng(2);
    const double n = 1.7;
    for (double deg : {0.0, 15.0, 30.0, 35.0}) {  // below the critical angle, 36.0 deg
        const Fresnel f = fresnel(n, 1, deg * kDeg);
        const UniaxialMedium glass{n, n, randomUnit(rng)};
        for (const PlaneWave& in : {ordinaryWave(glass, incoming(deg * kDeg) * -1.0),
                                    extraordinaryWave(glass, incoming(deg * kDeg) * -1.0)}) {
            const InterfaceWaves w = leaveCrystal(glass, in, {0, 0, 1});
            // The wave's field split over s and p, each transmitted as Fresnel says.
            const Vec3 s = w.transmitted[0].wave.field;
            const double fs = dot(in.field, s), fp2 = 1 - fs * fs;
            EXPECT_NEAR(w.transmitted[0].share[0], fs * fs * (1 - f.Rs), 1e-12) << deg;
            EXPECT_NEAR(w.transmitted[1].share[0], fp2 * (1 - f.Rp), 1e-12) << deg;
            EXPECT_NEAR(w.reflected[0].share[0] + w.reflected[1].share[0], fs * fs * f.Rs + fp2 * f.Rp,
                        1e-12);
        }
    }
}

TEST(Birefringence, BrewsterAngleReflectsNoP) {
    const double n = 1.5;
    const UniaxialMedium glass{n, n, {0.3, 0.4, std::sqrt(0.75)}};
    const InterfaceWaves outside = enterCrystal(glass, incoming(std::atan(n)), {0, 0, 1});
    EXPECT_LT(outside.reflected[1].share[1], 1e-24);
    EXPECT_GT(outside.reflected[0].share[0], 0.1);
    // From inside, Brewster's angle is atan(1 / n); with the axis along s the ordinary wave is pure p.
    const UniaxialMedium axisAlongS{n, n, {0, 1, 0}};
    const PlaneWave p = ordinaryWave(axisAlongS, incoming(std::atan(1 / n)) * -1.0);
    const InterfaceWaves inside = leaveCrystal(axisAlongS, p, {0, 0, 1});
    EXPECT_LT(inside.reflected[0].share[0] + inside.reflected[1].share[0], 1e-24);
}

// Every outgoing ray leaves on its own side of the facet (outward normal `normal`): reflected rays back,
// transmitted rays across. Returns how many of them have a wave normal pointing the other way (an
// extraordinary wave in a strongly birefringent crystal near grazing), the case where the energy flow, not
// the wave normal, must choose.
int countRaysOnTheirSide(const InterfaceWaves& w, const Vec3& normal) {
    const double towardsReflected = w.incidentCount == 2 ? 1 : -1;
    int backward = 0;
    for (int j = 0; j < 2; ++j) {
        for (const auto& [o, side] : {std::pair{&w.reflected[j], towardsReflected},
                                      std::pair{&w.transmitted[j], -towardsReflected}}) {
            if (!o->propagating) continue;
            EXPECT_GT(side * dot(o->wave.ray, normal), 0);
            if (side * dot(o->wave.waveNormal, normal) < 0) ++backward;
        }
    }
    return backward;
}

TEST(Birefringence, EnergyIsConservedFromOutside) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> index(1.3, 2.8), unit(0, 1);
    int backwardWaveNormals = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const UniaxialMedium crystal{index(rng), index(rng), randomUnit(rng)};
        const Vec3 normal = randomUnit(rng);
        Vec3 d = randomUnit(rng);
        if (dot(d, normal) > -1e-3) d = d - normal * (2 * dot(d, normal));
        if (dot(d, normal) > -1e-3) continue;
        // Mostly air; sometimes a denser liquid, where a crystal's wave normals can point backwards.
        const double outside = trial % 4 ? 1.0 : index(rng);
        const InterfaceWaves w = enterCrystal(crystal, d, normal, outside);
        for (int basis = 0; basis < 2; ++basis) EXPECT_NEAR(totalShare(w, basis), 1, 1e-12) << trial;
        backwardWaveNormals += countRaysOnTheirSide(w, normal);
        // Any coherent or partial state: the outgoing shares add up to the incident intensity.
        const double a = unit(rng), phase = 2 * kPi * unit(rng);
        const Coherency j{a, 1 - a, std::polar(std::sqrt(a * (1 - a)) * unit(rng), phase)};
        double sum = 0;
        for (const OutgoingWave* o :
             {&w.reflected[0], &w.reflected[1], &w.transmitted[0], &w.transmitted[1]}) {
            EXPECT_GE(o->fluxRatio, 0);
            sum += shareOf(*o, j);
        }
        EXPECT_NEAR(sum, 1, 1e-12) << trial;
    }
    EXPECT_GT(backwardWaveNormals, 0);
}

TEST(Birefringence, EnergyIsConservedFromInsideWithTotalInternalReflection) {
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> index(1.3, 2.8);
    int total = 0, totalInternal = 0, partial = 0, backwardWaveNormals = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        const UniaxialMedium crystal{index(rng), index(rng), randomUnit(rng)};
        const Vec3 k = randomUnit(rng);
        const PlaneWave in = trial % 2 ? ordinaryWave(crystal, k) : extraordinaryWave(crystal, k);
        Vec3 normal = randomUnit(rng);
        if (dot(in.ray, normal) < 0) normal = -normal;
        if (dot(in.ray, normal) < 1e-3) continue;
        const InterfaceWaves w = leaveCrystal(crystal, in, normal);
        ++total;
        EXPECT_NEAR(totalShare(w, 0), 1, 1e-12) << trial;
        backwardWaveNormals += countRaysOnTheirSide(w, normal);
        if (w.totalInternalReflection()) {
            ++totalInternal;
            EXPECT_EQ(w.transmitted[0].share[0] + w.transmitted[1].share[0], 0);
        }
        // One reflected wave evanescent while light still leaves: possible in a crystal only.
        if (!w.reflected[0].propagating || !w.reflected[1].propagating) ++partial;
    }
    EXPECT_GT(totalInternal, total / 5);
    EXPECT_LT(totalInternal, total);
    EXPECT_GT(partial, 0);
    EXPECT_GT(backwardWaveNormals, 0);
}

// Reciprocity (Lorentz; eps is symmetric): a wave the facet lets in, sent back along its own ray, leaves into
// air along the incoming light's path, each of s and p taking the share that the same polarisation gave it
// coming in. Ties the two entry points together.
TEST(Birefringence, TransmissionIsReciprocal) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> index(1.3, 2.8);
    for (int trial = 0; trial < 500; ++trial) {
        const UniaxialMedium crystal{index(rng), index(rng), randomUnit(rng)};
        const Vec3 normal = randomUnit(rng);
        Vec3 d = randomUnit(rng);
        if (dot(d, normal) > 0) d = -d;
        if (dot(d, normal) > -1e-2) continue;
        const InterfaceWaves in = enterCrystal(crystal, d, normal);
        for (const OutgoingWave& t : in.transmitted) {
            PlaneWave back = t.wave;
            back.waveNormal = -back.waveNormal;
            back.ray = -back.ray;
            const InterfaceWaves out = leaveCrystal(crystal, back, normal);
            EXPECT_NEAR(length(out.transmitted[0].wave.ray + d), 0, 1e-12);
            EXPECT_NEAR(out.transmitted[0].share[0], t.share[0], 1e-12) << trial;
            EXPECT_NEAR(out.transmitted[1].share[0], t.share[1], 1e-12) << trial;
        }
    }
}

TEST(Birefringence, TotalInternalReflectionReflectsEverythingWithPhases) {
    const UniaxialMedium sapphire{1.768, 1.760, normalize(Vec3{1, 2, 3})};
    const PlaneWave in = ordinaryWave(sapphire, incoming(50 * kDeg) * -1.0);  // critical angle ~34.5 deg
    const InterfaceWaves w = leaveCrystal(sapphire, in, {0, 0, 1});
    ASSERT_TRUE(w.totalInternalReflection());
    EXPECT_EQ(w.transmitted[0].share[0], 0);
    EXPECT_EQ(w.transmitted[1].share[0], 0);
    EXPECT_NEAR(w.reflected[0].share[0] + w.reflected[1].share[0], 1, 1e-12);
    // The reflection is not real: total internal reflection shifts the phase.
    EXPECT_GT(std::abs(std::arg(w.reflected[0].amplitude[0])), 0.1);
}

// Fresnel's rhomb (docs/optics.md): glass of 1.51 at 54.6 deg; total internal reflection delays p against s
// by d_p - d_s = 45 deg, with tan(d_s/2) = sqrt(sin^2 i - n^2) / cos i and tan(d_p/2) = the same / n^2
// (n = 1 / 1.51).
TEST(Birefringence, TotalInternalReflectionPhasesAreFresnels) {
    const double n1 = 1.51, i = 54.6 * kDeg, n = 1 / n1;
    const double root = std::sqrt(std::sin(i) * std::sin(i) - n * n);
    const double ds = 2 * std::atan(root / std::cos(i)), dp = 2 * std::atan(root / (n * n * std::cos(i)));
    EXPECT_NEAR((dp - ds) / kDeg, 45.0, 0.05);
    // With the axis in the plane of incidence the ordinary wave is s, the extraordinary one p.
    const UniaxialMedium glass{n1, n1, normalize(Vec3{1, 0, 1})};
    const Vec3 k = incoming(i) * -1.0;
    const InterfaceWaves ws = leaveCrystal(glass, ordinaryWave(glass, k), {0, 0, 1});
    const InterfaceWaves wp = leaveCrystal(glass, extraordinaryWave(glass, k), {0, 0, 1});
    ASSERT_TRUE(ws.totalInternalReflection());
    // The reflected field over s, p = k_r x s, relative to the incident field over the same basis.
    const Vec3 s{0, 1, 0}, kr{-std::sin(i), 0, -std::cos(i)};
    auto reflectedAlong = [&](const InterfaceWaves& w, const Vec3& e) {
        return w.reflected[0].amplitude[0] * dot(w.reflected[0].wave.field, e) +
               w.reflected[1].amplitude[0] * dot(w.reflected[1].wave.field, e);
    };
    const Complex rs = reflectedAlong(ws, s) / dot(ws.incident[0].field, s);
    const Complex rp = reflectedAlong(wp, cross(kr, s)) / dot(wp.incident[0].field, cross(k, s));
    EXPECT_NEAR(std::abs(rs), 1, 1e-12);
    EXPECT_NEAR(std::abs(rp), 1, 1e-12);
    // Fields go as exp(i (k.r - w t)) and the evanescent wave decays: the phases are -d_s and -d_p.
    EXPECT_NEAR(std::arg(rs), -ds, 1e-9);
    EXPECT_NEAR(std::arg(rp / rs), -(dp - ds), 1e-9);
    // The same from the other side: glass outside, an isotropic "crystal" of index 1 whose two waves are both
    // evanescent, and which must decay into it for the phases to be the same.
    const UniaxialMedium vacuum{1, 1, normalize(Vec3{1, 2, 2})};
    const InterfaceWaves out = enterCrystal(vacuum, incoming(i), {0, 0, 1}, n1);
    ASSERT_TRUE(out.totalInternalReflection());
    EXPECT_NEAR(out.reflected[0].share[0] + out.reflected[1].share[0], 1, 1e-12);
    EXPECT_NEAR(std::arg(out.reflected[0].amplitude[0]), -ds, 1e-9);
    EXPECT_NEAR(std::arg(out.reflected[1].amplitude[1]), -dp, 1e-9);
}

TEST(Birefringence, WaveNormalsObeySnell) {
    std::mt19937_64 rng(5);
    const UniaxialMedium calcite{1.6584, 1.4864, randomUnit(rng)};
    for (double deg : {5.0, 20.0, 40.0, 60.0, 80.0}) {
        const double i = deg * kDeg;
        const InterfaceWaves w = enterCrystal(calcite, incoming(i), {0, 0, 1});
        const PlaneWave& o = w.transmitted[0].wave;
        const PlaneWave& e = w.transmitted[1].wave;
        EXPECT_EQ(o.mode, WaveMode::Ordinary);
        EXPECT_EQ(e.mode, WaveMode::Extraordinary);
        // Both wave normals in the plane of incidence, bent as Snell says with their own index.
        EXPECT_NEAR(o.waveNormal.y, 0, 1e-15);
        EXPECT_NEAR(e.waveNormal.y, 0, 1e-15);
        EXPECT_NEAR(o.index, calcite.nO, 1e-13);
        EXPECT_NEAR(o.index * o.waveNormal.x, std::sin(i), 1e-13);
        EXPECT_NEAR(e.index, extraordinaryIndex(calcite, e.waveNormal), 1e-13);
        EXPECT_NEAR(e.index * e.waveNormal.x, std::sin(i), 1e-13);
        EXPECT_LT(o.waveNormal.z, 0);
        EXPECT_LT(e.ray.z, 0);
        // The reflected waves go back up at the mirror angle.
        EXPECT_NEAR(w.reflected[0].wave.waveNormal.x, std::sin(i), 1e-15);
        EXPECT_NEAR(w.reflected[0].wave.waveNormal.z, std::cos(i), 1e-15);
    }
}

// A cleavage rhomb of calcite (n_o 1.6584, n_e 1.4864 at 589 nm: Hecht, Optics, ch. 8; Born & Wolf ch. 15) at
// normal incidence, the optic axis 44.6 deg from the face normal. The e ray leaves the wave normal (the face
// normal) by rho: its ray is along eps k, at tan(phi) = (n_o^2 / n_e^2) tan(theta) from the axis, so
// tan(rho) = tan(phi - theta) = (n_o^2 - n_e^2) sin t cos t / (n_e^2 cos^2 t + n_o^2 sin^2 t) = 6.23 deg
// (docs/optics.md); a 10 mm rhomb shows two images 10 tan(rho) = 1.09 mm apart.
TEST(Birefringence, CalciteRhombWalkOff) {
    const double no = 1.6584, ne = 1.4864, t = 44.6 * kDeg;
    const UniaxialMedium calcite{no, ne, {std::sin(t), 0, std::cos(t)}};
    const InterfaceWaves w = enterCrystal(calcite, {0, 0, -1}, {0, 0, 1});
    const PlaneWave& o = w.transmitted[0].wave;
    const PlaneWave& e = w.transmitted[1].wave;
    EXPECT_NEAR(o.ray.z, -1, 1e-15);
    EXPECT_NEAR(e.waveNormal.z, -1, 1e-15);
    const double rho = std::acos(-e.ray.z);
    const double closed =
        std::atan((no * no - ne * ne) * std::sin(t) * std::cos(t) /
                  (ne * ne * std::cos(t) * std::cos(t) + no * no * std::sin(t) * std::sin(t)));
    EXPECT_NEAR(rho, closed, 1e-12);
    EXPECT_NEAR(rho / kDeg, 6.23, 0.005);
    // Walk-off in the principal plane (the axis and the normal), away from the axis in a negative crystal.
    EXPECT_NEAR(e.ray.y, 0, 1e-15);
    EXPECT_LT(std::fabs(dot(e.ray, calcite.axis)), std::fabs(dot(e.waveNormal, calcite.axis)));
    const double separationMm = 10 * std::fabs(e.ray.x / e.ray.z);
    EXPECT_NEAR(separationMm, 1.092, 0.001);
    // Light polarised across the principal plane (along y) enters wholly as the o wave, light polarised in it
    // (along x) wholly as the e wave, each reflected as from glass of its index along the normal: at normal
    // incidence only E's tangential part enters the boundary conditions, with H = n z x E_t.
    auto coherent = [&](const Vec3& e) {
        const double as = dot(e, w.incident[0].field), ap = dot(e, w.incident[1].field);
        return Coherency{as * as, ap * ap, as * ap};
    };
    const double nTheta = extraordinaryIndex(calcite, {0, 0, 1});
    EXPECT_NEAR(nTheta,
                1 / std::sqrt(std::cos(t) * std::cos(t) / (no * no) + std::sin(t) * std::sin(t) / (ne * ne)),
                1e-15);
    EXPECT_NEAR(e.index, nTheta, 1e-15);
    EXPECT_NEAR(shareOf(w.transmitted[0], coherent({0, 1, 0})), 1 - fresnel(1, no, 0).Rs, 1e-12);
    EXPECT_NEAR(shareOf(w.transmitted[1], coherent({0, 1, 0})), 0, 1e-12);
    EXPECT_NEAR(shareOf(w.transmitted[1], coherent({1, 0, 0})), 1 - fresnel(1, nTheta, 0).Rs, 1e-12);
    EXPECT_NEAR(shareOf(w.transmitted[0], coherent({1, 0, 0})), 0, 1e-12);
    // The e wave's field leans out of the face with its ray: E is perpendicular to the ray, not to k.
    EXPECT_NEAR(dot(e.field, e.ray), 0, 1e-15);
    EXPECT_GT(std::fabs(e.field.z), 0.1);
}

TEST(Birefringence, AxisAlongTheNormalDoesNotSplitAtNormalIncidence) {
    const UniaxialMedium calcite{1.6584, 1.4864, {0, 0, 1}};
    const InterfaceWaves w = enterCrystal(calcite, {0, 0, -1}, {0, 0, 1});
    for (const OutgoingWave& t : w.transmitted) {
        ASSERT_TRUE(t.propagating);
        EXPECT_NEAR(t.wave.index, 1.6584, 1e-13);
        EXPECT_NEAR(t.wave.ray.z, -1, 1e-15);
        EXPECT_NEAR(t.wave.waveNormal.z, -1, 1e-15);
    }
    // Both polarisations go in as they would into glass of n_o.
    const Fresnel f = fresnel(1, 1.6584, 0);
    for (int basis = 0; basis < 2; ++basis)
        EXPECT_NEAR(w.transmitted[0].share[basis] + w.transmitted[1].share[basis], 1 - f.Rs, 1e-12);
}

TEST(Birefringence, EigenmodeFieldsAreOrthogonal) {
    std::mt19937_64 rng(6);
    for (int trial = 0; trial < 500; ++trial) {
        const UniaxialMedium crystal{2.0, trial % 2 ? 2.2 : 1.8, randomUnit(rng)};
        const Vec3 k = randomUnit(rng);
        const PlaneWave o = ordinaryWave(crystal, k), e = extraordinaryWave(crystal, k);
        EXPECT_NEAR(dot(o.field, e.field), 0, 1e-12);
        EXPECT_NEAR(dot(o.field, crystal.axis), 0, 1e-12);
        EXPECT_NEAR(dot(o.field, k), 0, 1e-12);
        EXPECT_NEAR(length(o.ray - k), 0, 1e-12);
        // D = eps E is transverse; the ray (Poynting vector E x (k x E)) is perpendicular to E.
        const Vec3 d = e.field * (2.0 * 2.0) +
                       crystal.axis * (dot(crystal.axis, e.field) * (crystal.nE * crystal.nE - 4.0));
        EXPECT_NEAR(dot(d, k), 0, 1e-12);
        const Vec3 poynting = cross(e.field, cross(k, e.field));
        EXPECT_NEAR(length(normalize(poynting) - e.ray), 0, 1e-12);
        EXPECT_NEAR(e.index, extraordinaryIndex(crystal, k), 1e-15);
    }
    // Along the axis the two are degenerate: still two orthogonal fields, both of index n_o.
    const UniaxialMedium crystal{2.0, 2.2, {0, 0, 1}};
    const PlaneWave o = ordinaryWave(crystal, {0, 0, 1}), e = extraordinaryWave(crystal, {0, 0, 1});
    EXPECT_NEAR(dot(o.field, e.field), 0, 1e-15);
    EXPECT_NEAR(e.index, 2.0, 1e-15);
}

TEST(Birefringence, RefusesLightThatDoesNotMeetTheFacet) {
    const UniaxialMedium quartz{1.544, 1.553, {0, 0, 1}};
    EXPECT_THROW(enterCrystal(quartz, {0, 0, 1}, {0, 0, 1}), Error);
    EXPECT_THROW(leaveCrystal(quartz, ordinaryWave(quartz, {0, 0, -1}), {0, 0, 1}), Error);
    EXPECT_THROW(enterCrystal(UniaxialMedium{0, 1.5, {0, 0, 1}}, {0, 0, -1}, {0, 0, 1}), Error);
    EXPECT_THROW(enterCrystal(UniaxialMedium{1.5, 1.6, {0, 0, 2}}, {0, 0, -1}, {0, 0, 1}), Error);
    EXPECT_THROW(leaveCrystal(quartz, ordinaryWave(quartz, {0, 0, 1}), {0, 0, 1}, NAN), Error);
}

// Any unit vector across unit n.
Vec3 perpendicularTo(const Vec3& n) {
    return normalize(std::fabs(n.x) < 0.6 ? cross(n, Vec3{1, 0, 0}) : cross(n, Vec3{0, 1, 0}));
}
Vec3 toVec3Principal(const BiaxialMedium& b, const Vec3& v) {
    return {dot(b.x, v), dot(b.y, v), dot(b.z, v)};
}

// ---- Biaxial crystals ----

// Principal axes from a random rotation (the columns of a random orthonormal frame).
BiaxialMedium randomBiaxial(std::mt19937_64& rng, double alpha, double beta, double gamma) {
    const Vec3 z = randomUnit(rng), x = normalize(cross(z, randomUnit(rng)));
    return {alpha, beta, gamma, x, cross(z, x), z};
}
// A uniaxial crystal as a biaxial one: alpha == beta (positive, the axis along z) or beta == gamma
// (negative, along x).
BiaxialMedium asBiaxial(const UniaxialMedium& u) {
    const Vec3 a = u.axis, b = normalize(cross(a, perpendicularTo(a))), c = cross(a, b);
    if (u.nE > u.nO) return {u.nO, u.nO, u.nE, b, c, a};
    return {u.nE, u.nO, u.nO, a, b, c};
}
PlaneWave withMode(PlaneWave w, WaveMode mode) {
    w.mode = mode;
    return w;
}

// An outgoing wave's field per incident basis wave, amplitude times unit field: free of the field's sign.
void expectSameWave(const OutgoingWave& a, const OutgoingWave& b, int count, double tol, int trial) {
    ASSERT_EQ(a.propagating, b.propagating) << trial;
    for (int i = 0; i < count; ++i) EXPECT_NEAR(a.share[i], b.share[i], tol) << trial;
    if (!a.propagating) return;
    EXPECT_NEAR(length(a.wave.ray - b.wave.ray), 0, tol) << trial;
    EXPECT_NEAR(length(a.wave.waveNormal - b.wave.waveNormal), 0, tol) << trial;
    EXPECT_NEAR(a.wave.index, b.wave.index, tol) << trial;
    for (int i = 0; i < count; ++i) {
        const Vec3 d = a.wave.field * a.amplitude[i].real() - b.wave.field * b.amplitude[i].real();
        const Vec3 e = a.wave.field * a.amplitude[i].imag() - b.wave.field * b.amplitude[i].imag();
        EXPECT_NEAR(length(d) + length(e), 0, tol) << trial;
    }
}

// alpha == beta or beta == gamma is a uniaxial crystal: the general solver gives the uniaxial one's waves,
// amplitudes, directions and shares to rounding, both ways through the facet, total reflection included.
TEST(BiaxialCrystal, UniaxialLimitMatchesTheUniaxialSolver) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> index(1.4, 2.7);
    int totalInternal = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const UniaxialMedium u{index(rng), index(rng), randomUnit(rng)};
        const BiaxialMedium b = asBiaxial(u);
        const bool positive = u.nE > u.nO;
        const int o = positive ? 0 : 1,
                  e = 1 - o;  // the biaxial slots of the ordinary and extraordinary waves
        Vec3 normal = randomUnit(rng);
        const Vec3 d = randomUnit(rng);
        if (dot(d, normal) > 0) normal = -normal;
        if (dot(d, normal) > -1e-3) continue;
        const InterfaceWaves wu = enterCrystal(u, d, normal), wb = enterCrystal(b, d, normal);
        for (int r = 0; r < 2; ++r) expectSameWave(wb.reflected[r], wu.reflected[r], 2, 1e-9, trial);
        expectSameWave(wb.transmitted[o], wu.transmitted[0], 2, 1e-9, trial);
        expectSameWave(wb.transmitted[e], wu.transmitted[1], 2, 1e-9, trial);
        EXPECT_EQ(wb.transmitted[0].wave.mode, WaveMode::Fast);

        // From inside: the wave the facet let in, back to a facet of another normal.
        const int which = trial % 2;
        const PlaneWave inU = wu.transmitted[which].wave;
        Vec3 out = randomUnit(rng);
        if (dot(inU.ray, out) < 0) out = -out;
        if (dot(inU.ray, out) < 1e-3) continue;
        const PlaneWave inB = withMode(inU, (which == 0) == positive ? WaveMode::Fast : WaveMode::Slow);
        const InterfaceWaves lu = leaveCrystal(u, inU, out), lb = leaveCrystal(b, inB, out);
        totalInternal += lu.totalInternalReflection();
        EXPECT_EQ(lb.totalInternalReflection(), lu.totalInternalReflection()) << trial;
        for (int t = 0; t < 2; ++t) expectSameWave(lb.transmitted[t], lu.transmitted[t], 1, 1e-9, trial);
        expectSameWave(lb.reflected[o], lu.reflected[0], 1, 1e-9, trial);
        expectSameWave(lb.reflected[e], lu.reflected[1], 1, 1e-9, trial);
    }
    EXPECT_GT(totalInternal, 100);
}

// Snell's law for each wave: the tangential part of k is the incident light's, and each crystal wave's index
// is Fresnel's for its own wave normal (the Fast one the smaller).
TEST(BiaxialCrystal, EveryWaveKeepsTheTangentialWaveVector) {
    std::mt19937_64 rng(12);
    int checked = 0;
    for (int trial = 0; trial < 2000; ++trial) {
        const BiaxialMedium b = randomBiaxial(rng, 1.5, 1.7, 2.0);
        Vec3 normal = randomUnit(rng);
        const Vec3 d = randomUnit(rng);
        if (dot(d, normal) > 0) normal = -normal;
        if (dot(d, normal) > -1e-3) continue;
        const Vec3 kt = d - normal * dot(d, normal);
        const InterfaceWaves w = enterCrystal(b, d, normal);
        for (int j = 0; j < 2; ++j) {
            const PlaneWave& p = w.transmitted[j].wave;
            const Vec3 k = p.waveNormal * p.index;
            EXPECT_NEAR(length(k - normal * dot(k, normal) - kt), 0, 1e-12) << trial;
            EXPECT_NEAR(p.index, waveIndices(b, p.waveNormal)[j], 1e-12) << trial;
            EXPECT_GT(dot(p.ray, normal), 0 - 1.0) << trial;
            EXPECT_LT(dot(p.ray, normal), 0) << trial;  // energy into the crystal
            // D = eps E is across k (Maxwell's div D = 0).
            const Vec3 e = toVec3Principal(b, p.field), kp = toVec3Principal(b, k);
            EXPECT_NEAR(b.alpha * b.alpha * e.x * kp.x + b.beta * b.beta * e.y * kp.y +
                            b.gamma * b.gamma * e.z * kp.z,
                        0, 1e-12)
                << trial;
        }
        // Out again: the wave that came in, at its own facet, leaves along the incident direction.
        const PlaneWave& in = w.transmitted[trial % 2].wave;
        const InterfaceWaves back = leaveCrystal(b, in, -normal);
        if (back.transmitted[0].propagating) {
            EXPECT_NEAR(length(back.transmitted[0].wave.ray - d), 0, 1e-12) << trial;
            ++checked;
        }
        for (int j = 0; j < 2; ++j) {
            if (!back.reflected[j].propagating) continue;
            const PlaneWave& p = back.reflected[j].wave;
            const Vec3 k = p.waveNormal * p.index;
            EXPECT_NEAR(length(k - normal * dot(k, normal) - kt), 0, 1e-12) << trial;
            EXPECT_NEAR(p.index, waveIndices(b, p.waveNormal)[j], 1e-12) << trial;
        }
    }
    EXPECT_GT(checked, 1000);
}

// The shares of the four outgoing waves sum to 1 at random incidences and orientations, from outside (s and
// p) and from inside (either wave), total internal reflection included.
TEST(BiaxialCrystal, EnergyIsConservedOverTheSplit) {
    std::mt19937_64 rng(13);
    std::uniform_real_distribution<double> index(1.3, 2.8);
    int inside = 0, totalInternal = 0, partial = 0;
    for (int trial = 0; trial < 4000; ++trial) {
        double n[3] = {index(rng), index(rng), index(rng)};
        std::sort(n, n + 3);
        const BiaxialMedium b = randomBiaxial(rng, n[0], n[1], n[2]);
        Vec3 normal = randomUnit(rng);
        const Vec3 d = randomUnit(rng);
        if (dot(d, normal) > 0) normal = -normal;
        if (dot(d, normal) > -1e-4) continue;
        const InterfaceWaves w = enterCrystal(b, d, normal);
        EXPECT_NEAR(totalShare(w, 0), 1, 1e-10) << trial;
        EXPECT_NEAR(totalShare(w, 1), 1, 1e-10) << trial;

        const PlaneWave in = biaxialWave(b, randomUnit(rng), trial % 2 ? WaveMode::Fast : WaveMode::Slow);
        Vec3 out = randomUnit(rng);
        if (dot(in.ray, out) < 0) out = -out;
        if (dot(in.ray, out) < 1e-3) continue;
        const InterfaceWaves l = leaveCrystal(b, in, out);
        ++inside;
        // The quartic's roots of a wave and its reflected twin near grazing part by about the ray's normal
        // component, so their precision falls as it does (docs/optics.md, "Biaxial crystals", Precision).
        EXPECT_NEAR(totalShare(l, 0), 1, 1e-9) << trial;
        if (l.totalInternalReflection()) ++totalInternal;
        if (!l.reflected[0].propagating || !l.reflected[1].propagating) ++partial;
    }
    EXPECT_GT(totalInternal, inside / 5);
    EXPECT_LT(totalInternal, inside);
    EXPECT_GT(partial, 0);
}

// docs/optics.md, "Biaxial crystals", Precision: the worst sum of the shares over 200 000 random crystals,
// orientations and incidences (printed), entering and leaving by the leaving ray's normal component c, the
// cosine of its angle to the facet's normal (c below 1e-3: within 0.06 deg of grazing).
TEST(BiaxialCrystal, TheSharesSumToOneWithinTheStatedPrecision) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> index(1.3, 2.8);
    double entering = 0, leaving[3] = {};  // c above 1e-3, 1e-4 to 1e-3, below 1e-4
    int counts[3] = {};
    for (int trial = 0; trial < 200'000; ++trial) {
        double n[3] = {index(rng), index(rng), index(rng)};
        std::sort(n, n + 3);
        if (n[2] - n[0] < 1e-5)
            continue;  // a job's own material is refused so near (material_definition.cpp)
        const BiaxialMedium b = randomBiaxial(rng, n[0], n[1], n[2]);
        Vec3 normal = randomUnit(rng);
        const Vec3 d = randomUnit(rng);
        if (dot(d, normal) > 0) normal = -normal;
        if (dot(d, normal) < -1e-4) {
            const InterfaceWaves w = enterCrystal(b, d, normal);
            for (int basis = 0; basis < 2; ++basis)
                entering = std::max(entering, std::fabs(totalShare(w, basis) - 1));
        }
        const PlaneWave in = biaxialWave(b, randomUnit(rng), trial % 2 ? WaveMode::Fast : WaveMode::Slow);
        Vec3 out = randomUnit(rng);
        if (dot(in.ray, out) < 0) out = -out;
        const double c = dot(in.ray, out);
        if (c < 1e-7) continue;
        const int bin = c > 1e-3 ? 0 : c > 1e-4 ? 1 : 2;
        leaving[bin] = std::max(leaving[bin], std::fabs(totalShare(leaveCrystal(b, in, out), 0) - 1));
        ++counts[bin];
    }
    std::printf(
        "shares' sum less 1, worst: entering %.2g; leaving at c > 1e-3 %.2g (%d), 1e-4 to 1e-3 %.2g (%d), "
        "1e-7 to 1e-4 %.2g (%d)\n",
        entering, leaving[0], counts[0], leaving[1], counts[1], leaving[2], counts[2]);
    EXPECT_LT(entering, 2e-12);
    EXPECT_LT(leaving[0], 2e-9);
    EXPECT_LT(leaving[1], 1e-7);
    EXPECT_LT(leaving[2], 1e-3);
    EXPECT_GT(counts[1], 100);
    EXPECT_GT(counts[2], 10);
}

// Light entering straight down a face across an optic axis (a stone turned to look down it) goes on as the
// degenerate pair; where either wave meets a facet, the two incident roots of the quartic are one double
// root, which rounding may split into a pair with tiny imaginary parts. Taken for evanescent waves they stood
// in for the reflected ones: the shares summed to anything (up to 1e33) or the equations came out singular (a
// peridot trace with its axis along the table's normal failed). Every facet from 20 to 70 deg, all round.
TEST(BiaxialCrystal, WavesDownAnOpticAxisLeaveEveryFacetConservingEnergy) {
    for (const char* name : {"peridot", "topaz", "zoisite"}) {
        const std::array<double, 3> n = Material::byName(name).principalIndices(Material::kSodiumD);
        const auto medium = [&](double tiltDeg) {
            const std::array<Vec3, 3> axes = OpticAxisSettings{tiltDeg, 0, 0}.principalAxes();
            return BiaxialMedium{
                double(float(n[0])), double(float(n[1])), double(float(n[2])), axes[0], axes[1], axes[2]};
        };
        // The tilt that brings an optic axis onto +z: Z's angle to the optic axes, Vz.
        const double vz = std::acos(std::fabs(opticAxes(medium(0))[0].z)) * 180 / std::numbers::pi;
        const BiaxialMedium m = medium(vz);
        ASSERT_GT(std::fabs(opticAxes(m)[1].z), 1 - 1e-9) << name;
        const InterfaceWaves in = enterCrystal(m, {0, 0, -1}, {0, 0, 1});
        int facets = 0;
        for (int wave = 0; wave < 2; ++wave)
            for (double deg = 20; deg <= 70; deg += 0.5)
                for (double az = 0; az < 360; az += 5) {
                    const double t = radians(deg), a = radians(az);
                    const Vec3 facet{std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), -std::cos(t)};
                    const InterfaceWaves out = leaveCrystal(m, in.transmitted[wave].wave, facet);
                    ASSERT_NEAR(totalShare(out, 0), 1, 1e-6)
                        << name << " wave " << wave << " " << deg << " " << az;
                    ++facets;
                }
        EXPECT_EQ(facets, 2 * 101 * 72);
    }
}

// The tracer's facet normals are floats, off unit length by up to about 1e-7. The quartic takes a unit
// normal (k.k = kt.kt + q^2), and where two of its roots nearly meet (a weak birefringence, a wave normal
// near an optic axis) that error moved them by its square root, even into a complex pair taken for evanescent
// waves: a weakly biaxial stone then lost a third of its light (leakage 37 % against 8 %). The waves must not
// depend on the normal's length.
TEST(BiaxialCrystal, TheWavesDoNotDependOnTheFacetNormalsLength) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> uniform(0, 1);
    const std::array<double, 3> media[] = {
        {1.609, 1.6093, 1.615}, {1.654, 1.671, 1.689}, {1.692, 1.693, 1.7}};
    int compared = 0;
    for (const auto& n : media)
        for (int trial = 0; trial < 1500; ++trial) {
            const BiaxialMedium m = randomBiaxial(rng, n[0], n[1], n[2]);
            // Half of the waves within a thousandth of a radian of an optic axis.
            Vec3 k = randomUnit(rng);
            if (trial % 2) {
                const Vec3 axis = opticAxes(m)[trial % 4 / 2];
                k = normalize(axis + normalize(cross(axis, randomUnit(rng))) * (1e-3 * uniform(rng)));
            }
            const PlaneWave wave = biaxialWave(m, k, trial % 3 ? WaveMode::Fast : WaveMode::Slow);
            Vec3 facet = randomUnit(rng);
            if (dot(wave.ray, facet) < 0) facet = -facet;
            if (dot(wave.ray, facet) < 0.05 || dot(wave.waveNormal, facet) < 0.05) continue;
            const InterfaceWaves unit = leaveCrystal(m, wave, facet);
            ASSERT_NEAR(totalShare(unit, 0), 1, 1e-6) << trial;
            for (double stretch : {1 + 1e-7, 1 - 1e-7}) {
                const InterfaceWaves off = leaveCrystal(m, wave, facet * stretch);
                for (int j = 0; j < 2; ++j) {
                    ASSERT_NEAR(off.reflected[j].share[0], unit.reflected[j].share[0], 1e-6) << trial;
                    ASSERT_NEAR(off.transmitted[j].share[0], unit.transmitted[j].share[0], 1e-6) << trial;
                }
            }
            ++compared;
        }
    EXPECT_GT(compared, 2000);
}

// A wave within 1e-5 rad of an optic axis has a twin on the other sheet a few tenths of a millionth away in
// q; rounding turned the two into a complex pair taken for evanescent reflected waves, and the shares summed
// to anything from 0.04 to 1e4 (0.7 % of such leavings). The incident wave's own root tells them apart.
TEST(BiaxialCrystal, WavesNextToAnOpticAxisConserveEnergyLeaving) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> uniform(0, 1);
    const std::array<double, 3> media[] = {{1.654, 1.671, 1.689}, {1.61, 1.613, 1.62}, {1.692, 1.693, 1.7}};
    int compared = 0;
    for (const auto& n : media)
        for (int trial = 0; trial < 3000; ++trial) {
            const BiaxialMedium m = randomBiaxial(rng, n[0], n[1], n[2]);
            const Vec3 axis = opticAxes(m)[trial % 2];
            const Vec3 k = normalize(axis + normalize(cross(axis, randomUnit(rng))) * (1e-5 * uniform(rng)));
            const PlaneWave wave = biaxialWave(m, k, trial % 4 < 2 ? WaveMode::Fast : WaveMode::Slow);
            Vec3 facet = randomUnit(rng);
            if (dot(wave.ray, facet) < 0) facet = -facet;
            if (dot(wave.ray, facet) < 0.05 || dot(wave.waveNormal, facet) < 0.05) continue;
            ASSERT_NEAR(totalShare(leaveCrystal(m, wave, facet), 0), 1, 1e-6) << trial;
            ++compared;
        }
    EXPECT_GT(compared, 3000);
}

// The two indices along a wave normal solve Fresnel's equation of wave normals in Born & Wolf's form,
// sum_k s_k^2 / (v^2 - v_k^2) = 0 with v = 1 / n (eq. 15.2.(24)), written without its poles:
// sum_k s_k^2 prod_(j != k) (v^2 - v_j^2) = 0; and each wave's field is the wave matrix's null vector.
TEST(BiaxialCrystal, WaveIndicesSolveFresnelsEquation) {
    std::mt19937_64 rng(14);
    const BiaxialMedium peridot{1.635, 1.651, 1.670, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int trial = 0; trial < 500; ++trial) {
        const Vec3 s = randomUnit(rng);
        const std::array<double, 2> n = waveIndices(peridot, s);
        EXPECT_LE(n[0], n[1]);
        EXPECT_GE(n[0], peridot.alpha - 1e-12);
        EXPECT_LE(n[1], peridot.gamma + 1e-12);
        const double vk[3] = {1 / (peridot.alpha * peridot.alpha), 1 / (peridot.beta * peridot.beta),
                              1 / (peridot.gamma * peridot.gamma)};
        const double sk[3] = {s.x * s.x, s.y * s.y, s.z * s.z};
        for (int j = 0; j < 2; ++j) {
            const double v = 1 / (n[j] * n[j]);
            const double f = sk[0] * (v - vk[1]) * (v - vk[2]) + sk[1] * (v - vk[0]) * (v - vk[2]) +
                             sk[2] * (v - vk[0]) * (v - vk[1]);
            EXPECT_NEAR(f, 0, 1e-15) << trial;
            const PlaneWave w = biaxialWave(peridot, s, j ? WaveMode::Slow : WaveMode::Fast);
            EXPECT_DOUBLE_EQ(w.index, n[j]);
            // k x (k x E) + eps E = 0.
            const Vec3 k = s * n[j], e = w.field;
            const Vec3 epsE{e.x * peridot.alpha * peridot.alpha, e.y * peridot.beta * peridot.beta,
                            e.z * peridot.gamma * peridot.gamma};
            EXPECT_NEAR(length(cross(k, cross(k, e)) + epsE), 0, 1e-12) << trial;
        }
    }
    // Along the principal axes the indices are the other two principal ones.
    const std::array<double, 2> alongZ = waveIndices(peridot, {0, 0, 1});
    EXPECT_NEAR(alongZ[0], peridot.alpha, 1e-15);
    EXPECT_NEAR(alongZ[1], peridot.beta, 1e-15);
}

// Along either optic axis (binormal), at Vz from z in the x-z plane with
// tan Vz = (gamma / alpha) sqrt((beta^2 - alpha^2) / (gamma^2 - beta^2)), both indices are beta; a degree off
// they part. Peridot (Fo100): 2Vz = 86.0 deg (docs/optics.md, "Doubly refracting materials").
TEST(BiaxialCrystal, BothIndicesAreBetaAlongTheOpticAxes) {
    std::mt19937_64 rng(15);
    const double a = 1.635, b = 1.651, g = 1.670;
    const BiaxialMedium peridot = randomBiaxial(rng, a, b, g);
    const double vz = std::atan(g / a * std::sqrt((b * b - a * a) / (g * g - b * b)));
    EXPECT_NEAR(2 * vz / kDeg, 86.0, 0.05);
    const std::array<Vec3, 2> axes = opticAxes(peridot);
    for (const Vec3& axis : axes) {
        EXPECT_NEAR(std::acos(dot(axis, peridot.z)), vz, 1e-9);
        EXPECT_NEAR(dot(axis, peridot.y), 0, 1e-12);
        const std::array<double, 2> n = waveIndices(peridot, axis);
        EXPECT_NEAR(n[0], b, 1e-9);
        EXPECT_NEAR(n[1], b, 1e-9);
        const Vec3 off = normalize(axis + peridot.y * std::tan(kDeg));
        const std::array<double, 2> m = waveIndices(peridot, off);
        EXPECT_GT(m[1] - m[0], 1e-4);
        // The degenerate waves along the axis still have orthogonal D = eps E.
        auto displacement = [&](WaveMode mode) {
            const Vec3 e = toVec3Principal(peridot, biaxialWave(peridot, axis, mode).field);
            return Vec3{a * a * e.x, b * b * e.y, g * g * e.z};
        };
        EXPECT_NEAR(dot(displacement(WaveMode::Fast), displacement(WaveMode::Slow)), 0, 1e-12);
    }
    EXPECT_GT(dot(axes[0], peridot.x), 0);
    // Light entering a plate cut across an optic axis at normal incidence: both waves at beta, energy kept.
    const InterfaceWaves w = enterCrystal(peridot, -axes[0], axes[0]);
    EXPECT_NEAR(w.transmitted[0].wave.index, b, 1e-7);
    EXPECT_NEAR(w.transmitted[1].wave.index, b, 1e-7);
    EXPECT_NEAR(totalShare(w, 0), 1, 1e-9);
    EXPECT_NEAR(totalShare(w, 1), 1, 1e-9);
}

// Next to an optic axis the outer sheet of the index surface is dimpled (there the two sheets meet in a
// cone), so a line of fixed kt just beyond beta along the axis misses the inner sheet and crosses the outer
// one four times: its waves leaving each side are the second and fourth roots, not the last two. Light from
// an immersion liquid of index 1.8 into peridot: both transmitted waves are on the slow sheet with their
// energy into the crystal; back out through a parallel face, both reflected waves on it too, their energy
// back in; the energy is kept both ways.
TEST(BiaxialCrystal, BothWavesOnTheOuterSheetWhereItsDimpleIsCrossed) {
    const BiaxialMedium peridot{1.635, 1.651, 1.670, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const Vec3 N{0, 1, 0}, axis = opticAxes(peridot)[0];  // N across the axis, into the crystal
    const double nOutside = 1.8;
    auto onSlowSheet = [&](const OutgoingWave& w, double side) {
        ASSERT_TRUE(w.propagating);
        const std::array<double, 2> n = waveIndices(peridot, w.wave.waveNormal);
        EXPECT_NEAR(w.wave.index, n[1], 1e-12);
        EXPECT_GT(w.wave.index - n[0], 1e-6);
        EXPECT_GT(side * dot(w.wave.ray, N), 1e-3);
    };
    for (double beyond : {1e-6, 1e-5, 3e-5}) {
        const Vec3 kt = axis * (peridot.beta + beyond);
        const Vec3 d = normalize(kt / nOutside + N * std::sqrt(1 - dot(kt, kt) / (nOutside * nOutside)));
        const InterfaceWaves in = enterCrystal(peridot, d, -N, nOutside);
        for (const OutgoingWave& t : in.transmitted) onSlowSheet(t, 1);
        EXPECT_NEAR(totalShare(in, 0), 1, 1e-10) << beyond;
        EXPECT_NEAR(totalShare(in, 1), 1, 1e-10) << beyond;
        for (const OutgoingWave& t : in.transmitted) {
            const InterfaceWaves out = leaveCrystal(peridot, t.wave, N, nOutside);
            for (const OutgoingWave& r : out.reflected) onSlowSheet(r, -1);
            EXPECT_NEAR(totalShare(out, 0), 1, 1e-10) << beyond;
        }
    }
}

TEST(BiaxialCrystal, RefusesBadMedia) {
    const BiaxialMedium unordered{1.7, 1.6, 1.8, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    EXPECT_THROW(enterCrystal(unordered, {0, 0, -1}, {0, 0, 1}), Error);
    const BiaxialMedium skew{1.6, 1.7, 1.8, {1, 0, 0}, {0.6, 0.8, 0}, {0, 0, 1}};
    EXPECT_THROW(enterCrystal(skew, {0, 0, -1}, {0, 0, 1}), Error);
    const BiaxialMedium ok{1.6, 1.7, 1.8, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    EXPECT_THROW(leaveCrystal(ok, ordinaryWave(UniaxialMedium{1.6, 1.7, {0, 0, 1}}, {0, 0, 1}), {0, 0, 1}),
                 Error);
}

}  // namespace
}  // namespace facetlight
