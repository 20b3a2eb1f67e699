// The entry into and the leaving from a uniaxial crystal computed in lanes of doubles
// (optics/uniaxial_interface-inl.h) against enterCrystal() and leaveCrystal() one incidence at a time, and
// the lanes' draws among an entry's and a leaving's waves against the one-photon walk's: the same bits, on
// every SIMD target this machine runs.
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "optics/uniaxial_interface_test.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "optics/uniaxial_interface-inl.h"
#include "util/random.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {

// enterUniaxialLanes(); nothing on Highway's one-lane fallback, which has no lanes of doubles. And
// drawEntryLanes() for photons in state pol along d whose streams are at state[j]: the wave drawn into
// drawn[j] (-1 reflected, 0 or 1 the ordinary or extraordinary wave).
uint64_t EnterLanes(const Vec3& axis, double nOutside, const double* nO, const double* nE,
                    const double* const direction[3], const double* const normal[3], size_t count,
                    const Polarization& pol, const Vec3f& d, const uint64_t* state, InterfaceWaves* out,
                    int* drawn) {
#if HWY_TARGET != HWY_SCALAR
    // What a photon's choice reads through uniaxial::EntryLane, into out[j] (enterCrystal()'s waves when
    // called, each number read replaced by the lanes'): the comparison with enterCrystal() checks those.
    using Entry = uniaxial::UniaxialEntry<double>;
    constexpr size_t kStride = 16;
    alignas(64) double numbers[Entry::kNumbers * kStride];
    const uint64_t entered =
        enterUniaxialLanes(axis, nOutside, nO, nE, direction, normal, count, numbers, kStride);
    uint64_t reflected = 0, ordinary = 0;
    drawEntryLanes(pol, d, numbers, kStride, state, count, reflected, ordinary);
    for (uint64_t b = entered; b; b &= b - 1) {
        const int j = __builtin_ctzll(b);
        InterfaceWaves& w = out[j];
        const uniaxial::EntryLane lane{numbers + j, kStride};
        w.incident[0].field = lane.incidentS();
        for (int k = 0; k < 4; ++k) {
            OutgoingWave& o = k < 2 ? w.reflected[k] : w.transmitted[k - 2];
            o.fluxRatio = lane.fluxRatio(k);
            o.amplitude[0] = lane.amplitude(k, 0), o.amplitude[1] = lane.amplitude(k, 1);
        }
        for (int k = 0; k < 2; ++k) w.transmitted[k].wave = lane.transmittedWave(k);
        w.transmitted[0].wave.waveNormal = lane.ordinaryNormal();
        drawn[j] = reflected >> j & 1 ? -1 : ordinary >> j & 1 ? 0 : 1;
    }
    return entered;
#else
    (void)axis, (void)nOutside, (void)nO, (void)nE, (void)direction, (void)normal, (void)count, (void)pol,
        (void)d, (void)state, (void)out, (void)drawn;
    return 0;
#endif
}

// leaveUniaxialLanes(), as EnterLanes; and drawLeavingLanes() for photons whose streams are at state[j]:
// the wave drawn into drawn[j] (-1 out, 0 or 1 the reflected ordinary or extraordinary wave).
uint64_t LeaveLanes(const Vec3& axis, double nOutside, const double* nO, const double* nE,
                    const PlaneWave* const incident[], const double* const normal[3], size_t count,
                    const uint64_t* state, InterfaceWaves* out, int* drawn) {
#if HWY_TARGET != HWY_SCALAR
    // What a photon's choice reads through uniaxial::LeavingLane, into out[j] (leaveCrystal()'s waves when
    // called, each number read replaced by the lanes'), as EnterLanes.
    using Leaving = uniaxial::UniaxialLeaving<double>;
    constexpr size_t kStride = 16;
    alignas(64) double numbers[Leaving::kNumbers * kStride];
    uint64_t evanescent = 0;
    const uint64_t left =
        leaveUniaxialLanes(axis, nOutside, nO, nE, incident, normal, count, numbers, kStride, evanescent);
    uint64_t leaves = 0, ordinary = 0;
    drawLeavingLanes(numbers, kStride, state, count, leaves, ordinary);
    for (uint64_t b = left; b; b &= b - 1) {
        const int j = __builtin_ctzll(b);
        const bool outsideEvanescent = evanescent >> j & 1;
        InterfaceWaves& w = out[j];
        const uniaxial::LeavingLane lane{numbers + j, kStride, outsideEvanescent};
        for (int k = 0; k < 2; ++k) {
            w.reflected[k].share[0] = lane.reflectedShare(k);
            w.reflected[k].wave = lane.reflectedWave(k);
            w.transmitted[k].share[0] = lane.transmittedShare(k);
            w.transmitted[k].amplitude[0] = lane.transmittedAmplitude(k);
        }
        w.transmitted[0].wave.ray = lane.transmittedRay();
        w.transmitted[0].wave.field = lane.transmittedField();
        drawn[j] = leaves >> j & 1 ? -1 : ordinary >> j & 1 ? 0 : 1;
    }
    return left;
#else
    (void)axis, (void)nOutside, (void)nO, (void)nE, (void)incident, (void)normal, (void)count, (void)state,
        (void)out, (void)drawn;
    return 0;
#endif
}

}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
#include "support/simd_targets.h"

namespace facetlight {
HWY_EXPORT(EnterLanes);
HWY_EXPORT(LeaveLanes);
namespace {

constexpr size_t kBatch = 16;  // up to a packet of AVX-512 float lanes, as the packet walk sends

Vec3 randomUnit(std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    return normalize(Vec3{g(rng), g(rng), g(rng)});
}

// Bit for bit, NaN payloads and the sign of zero included.
bool same(double a, double b) {
    return std::bit_cast<uint64_t>(a) == std::bit_cast<uint64_t>(b);
}
bool same(const Vec3& a, const Vec3& b) {
    return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}
bool same(const PlaneWave& a, const PlaneWave& b) {
    return a.mode == b.mode && same(a.waveNormal, b.waveNormal) && same(a.ray, b.ray) &&
           same(a.field, b.field) && same(a.index, b.index);
}
bool same(const OutgoingWave& a, const OutgoingWave& b) {
    bool s = same(a.wave, b.wave) && a.propagating == b.propagating && same(a.fluxRatio, b.fluxRatio);
    for (int i = 0; i < 2; ++i)
        s = s && same(a.amplitude[i].real(), b.amplitude[i].real()) &&
            same(a.amplitude[i].imag(), b.amplitude[i].imag()) && same(a.share[i], b.share[i]);
    return s;
}
bool same(const InterfaceWaves& a, const InterfaceWaves& b) {
    bool s = a.incidentCount == b.incidentCount;
    for (int i = 0; i < 2; ++i)
        s = s && same(a.incident[i], b.incident[i]) && same(a.reflected[i], b.reflected[i]) &&
            same(a.transmitted[i], b.transmitted[i]);
    return s;
}

// One batch: crystals of random indices about one axis, incidences from random directions, a share of them
// at normal incidence or along the axis (the branches the lanes take as selects).
struct Batch {
    Vec3 axis;
    size_t count = kBatch;
    alignas(64) double nO[kBatch], nE[kBatch], d[3][kBatch], n[3][kBatch];
};
Batch randomBatch(std::mt19937_64& rng) {
    // Birefringence up to calcite's (0.17) and beyond.
    std::uniform_real_distribution<double> index(1.3, 2.8), birefringence(-0.2, 0.2), u(0, 1);
    Batch b;
    b.axis = randomUnit(rng);
    b.count = 1 + rng() % kBatch;  // tails shorter than a vector too
    for (size_t j = 0; j < kBatch; ++j) {
        b.nO[j] = index(rng), b.nE[j] = b.nO[j] + birefringence(rng);
        Vec3 normal = randomUnit(rng), dir = randomUnit(rng);
        const double kind = u(rng);
        if (kind < 0.1) {
            dir = -normal;  // normal incidence
        } else if (kind < 0.15) {
            normal = -b.axis, dir = b.axis;  // along the axis at normal incidence
        } else if (dot(dir, normal) > 0) {
            dir = -dir;
        }
        for (int c = 0; c < 3; ++c) b.d[c][j] = dir[c], b.n[c][j] = normal[c];
    }
    return b;
}

TEST(UniaxialEntry, LanesGiveEnterCrystalsBitsOnEveryTarget) {
    test::forEachSimdTarget([] {
        std::mt19937_64 rng(28);
        std::uniform_real_distribution<double> u(0, 1);
        size_t compared = 0, incidences = 0, drawnWaves[3] = {};
        for (int round = 0; round < 500; ++round) {
            const Batch b = randomBatch(rng);
            std::vector<InterfaceWaves> ones(kBatch);
            for (size_t j = 0; j < b.count; ++j) {
                const Vec3 dir{b.d[0][j], b.d[1][j], b.d[2][j]}, normal{b.n[0][j], b.n[1][j], b.n[2][j]};
                ones[j] = enterCrystal(UniaxialMedium{b.nO[j], b.nE[j], b.axis}, dir, normal);
            }
            std::vector<InterfaceWaves> lanes = ones;
            const double* const d[3] = {b.d[0], b.d[1], b.d[2]};
            const double* const n[3] = {b.n[0], b.n[1], b.n[2]};
            // A random state along one direction for the draws (the lanes' share it).
            const Vec3f dir(randomUnit(rng));
            const double psi = 3 * u(rng), chi = u(rng) - 0.5, degree = u(rng);
            const Polarization pol{
                Stokes{1, float(degree * std::cos(chi) * std::cos(2 * psi)),
                       float(degree * std::cos(chi) * std::sin(2 * psi)), float(degree * std::sin(chi))},
                frameAcross(dir, Vec3f(randomUnit(rng)))};
            alignas(64) uint64_t state[kBatch];
            for (uint64_t& st : state) st = rng();
            int drawn[kBatch];
            const uint64_t met = HWY_DYNAMIC_DISPATCH(EnterLanes)(b.axis, 1, b.nO, b.nE, d, n, b.count, pol,
                                                                  dir, state, lanes.data(), drawn);
            ASSERT_EQ(met >> b.count, 0u);
            for (size_t j = 0; j < b.count; ++j) {
                ++incidences;
                if (!(met >> j & 1)) continue;
                ASSERT_TRUE(same(lanes[j], ones[j])) << "round " << round << ", incidence " << j;
                // The lanes' draw, as the one-photon walk draws from enterCrystal()'s waves by shareOf() and
                // coherencyOf(), the double instances of what the lanes run.
                const InterfaceWaves& one = ones[j];
                const Coherency c = coherencyOf(pol, dir, Vec3f(one.incident[0].field));
                const double reflected = shareOf(one.reflected[0], c) + shareOf(one.reflected[1], c);
                const double ordinary = shareOf(one.transmitted[0], c);
                Rng stream = Rng::resume(state[j]);
                const double x = stream.uniform() * (reflected + ordinary + shareOf(one.transmitted[1], c));
                ASSERT_EQ(drawn[j], x < reflected              ? -1
                                    : x < reflected + ordinary ? 0
                                                               : 1)
                    << "round " << round << ", incidence " << j;
                ++drawnWaves[drawn[j] + 1];
                ++compared;
            }
        }
        // Entering from air every wave propagates: each incidence is computed in lanes where there are lanes.
        if (hwy::SupportedTargets() != HWY_SCALAR) {
            EXPECT_EQ(compared, incidences);
            for (const size_t waves : drawnWaves) EXPECT_GT(waves, compared / 50);  // each wave drawn
        }
    });
}

// Crystal waves of random kind and wave normal meeting random facets from inside: partly out, or totally
// reflected (the outside waves evanescent), a share at normal incidence.
TEST(UniaxialLeaving, LanesGiveLeaveCrystalsBitsOnEveryTarget) {
    test::forEachSimdTarget([] {
        std::mt19937_64 rng(29);
        std::uniform_real_distribution<double> u(0, 1);
        size_t compared = 0, incidences = 0, out = 0, totallyReflected = 0, drawnWaves[3] = {};
        for (int round = 0; round < 500; ++round) {
            Batch b = randomBatch(rng);
            PlaneWave waves[kBatch];
            const PlaneWave* incident[kBatch];
            for (size_t j = 0; j < kBatch; ++j) {
                const UniaxialMedium crystal{b.nO[j], b.nE[j], b.axis};
                const Vec3 k = randomUnit(rng);
                waves[j] = u(rng) < 0.5 ? ordinaryWave(crystal, k) : extraordinaryWave(crystal, k);
                Vec3 normal = u(rng) < 0.05 ? waves[j].ray : randomUnit(rng);
                if (dot(waves[j].ray, normal) < 0) normal = -normal;
                for (int c = 0; c < 3; ++c) b.n[c][j] = normal[c];
                incident[j] = &waves[j];
            }
            std::vector<InterfaceWaves> ones(kBatch);
            for (size_t j = 0; j < b.count; ++j) {
                const Vec3 normal{b.n[0][j], b.n[1][j], b.n[2][j]};
                ones[j] = leaveCrystal(UniaxialMedium{b.nO[j], b.nE[j], b.axis}, waves[j], normal);
            }
            std::vector<InterfaceWaves> lanes = ones;
            const double* const n[3] = {b.n[0], b.n[1], b.n[2]};
            alignas(64) uint64_t state[kBatch];
            for (uint64_t& st : state) st = rng();
            int drawn[kBatch];
            const uint64_t met = HWY_DYNAMIC_DISPATCH(LeaveLanes)(b.axis, 1, b.nO, b.nE, incident, n, b.count,
                                                                  state, lanes.data(), drawn);
            ASSERT_EQ(met >> b.count, 0u);
            for (size_t j = 0; j < b.count; ++j) {
                ++incidences;
                const InterfaceWaves& one = ones[j];
                const bool crystalReal = one.reflected[0].propagating && one.reflected[1].propagating;
                if (!(met >> j & 1)) {
                    if (hwy::SupportedTargets() != HWY_SCALAR) {
                        EXPECT_FALSE(crystalReal);
                    }
                    continue;
                }
                ASSERT_TRUE(same(lanes[j], one)) << "round " << round << ", incidence " << j;
                // The lanes' draw, as the one-photon walk draws from leaveCrystal()'s shares.
                Rng stream = Rng::resume(state[j]);
                const uniaxial::WaveDraw<double> draw = uniaxial::drawWave<double>(
                    stream.uniform(), one.transmitted[0].share[0], one.transmitted[1].share[0],
                    one.reflected[0].share[0], one.reflected[1].share[0]);
                ASSERT_EQ(drawn[j], draw.pair       ? -1
                                    : draw.ordinary ? 0
                                                    : 1)
                    << "round " << round << ", incidence " << j;
                ++drawnWaves[drawn[j] + 1];
                ++compared;
                (one.totalInternalReflection() ? totallyReflected : out) += 1;
            }
        }
        if (hwy::SupportedTargets() != HWY_SCALAR) {
            // Only a crystal wave evanescent is left to leaveCrystal (above); both outside cases are met.
            EXPECT_GT(compared, incidences * 8 / 10);
            EXPECT_GT(out, compared / 10);
            EXPECT_GT(totallyReflected, compared / 10);
            for (const size_t waves : drawnWaves) EXPECT_GT(waves, compared / 20);  // each wave drawn
        }
    });
}

// The lanes' buffers hold kNumbers numbers a lane (photon_packet.cpp) and EntryLane and LeavingLane read them
// by those counts: forEachNumber stores exactly as many, so a number added there without its count (or a
// count changed without it) would write past them or shift what the lanes read.
TEST(UniaxialLanes, EachStoresItsCountOfNumbers) {
    uniaxial::UniaxialEntry<double> entry{};
    int numbers = 0;
    entry.forEachNumber([&](double&) { ++numbers; });
    EXPECT_EQ(numbers, uniaxial::UniaxialEntry<double>::kNumbers);
    uniaxial::UniaxialLeaving<double> leaving{};
    numbers = 0;
    leaving.forEachNumber([&](double&) { ++numbers; });
    EXPECT_EQ(numbers, uniaxial::UniaxialLeaving<double>::kNumbers);
}

TEST(UniaxialEntry, RefusedInputIsLeftToEnterCrystal) {
    test::forEachSimdTarget([] {
        alignas(64) double nO[kBatch], nE[kBatch], d[3][kBatch], n[3][kBatch];
        for (size_t j = 0; j < kBatch; ++j) {
            nO[j] = j % 2 ? 1.77 : -1.0, nE[j] = 1.76;  // a negative index in every other lane
            d[0][j] = 0, d[1][j] = 0, d[2][j] = -1, n[0][j] = 0, n[1][j] = 0.6, n[2][j] = 0.8;
        }
        const double* const dp[3] = {d[0], d[1], d[2]};
        const double* const np[3] = {n[0], n[1], n[2]};
        std::vector<InterfaceWaves> out(kBatch);
        const Polarization pol{Stokes{}, Vec3f(1, 0, 0)};
        const Vec3f dir(0, 0, -1);
        alignas(64) uint64_t state[kBatch] = {};
        int drawn[kBatch];
        const uint64_t met = HWY_DYNAMIC_DISPATCH(EnterLanes)(Vec3{0, 0, 1}, 1, nO, nE, dp, np, kBatch, pol,
                                                              dir, state, out.data(), drawn);
        EXPECT_EQ(met & 0x5555, 0u);
        EXPECT_EQ(HWY_DYNAMIC_DISPATCH(EnterLanes)(Vec3{0, 0, 2}, 1, nO, nE, dp, np, kBatch, pol, dir, state,
                                                   out.data(), drawn),
                  0u);
    });
}

}  // namespace
}  // namespace facetlight
#endif
