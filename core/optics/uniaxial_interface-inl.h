// Inside core/ (per SIMD target, included after hwy/foreach_target.h or hwy/highway.h): the entry into a
// uniaxial crystal (optics/uniaxial_interface.h) for several photons at once, lanes of doubles, with the bits
// of enterCrystal() for each.
#if defined(FACETLIGHT_UNIAXIAL_INTERFACE_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACETLIGHT_UNIAXIAL_INTERFACE_INL_H_
#undef FACETLIGHT_UNIAXIAL_INTERFACE_INL_H_
#else
#define FACETLIGHT_UNIAXIAL_INTERFACE_INL_H_
#endif

#include <algorithm>
#include <cstdint>

#include "hwy/highway.h"
#include "optics/uniaxial_interface.h"
#include "util/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {
#if HWY_TARGET != HWY_SCALAR

// Light from the isotropic medium of index nOutside entering crystals {nO[j], nE[j], axis} along unit
// direction[j] through facets of unit outward normal[j], for j < count (each array readable up to count
// rounded up to a whole vector of doubles): for each j whose bit is set in the result (every wave
// propagating, no degenerate direction), enterCrystal(...)'s waves as uniaxial::EntryLane{numbers + j,
// stride} reads them (UniaxialEntry's numbers, number i at numbers[i * stride + j]; stride at least count
// rounded up to a whole vector of doubles); the others are left to enterCrystal.
HWY_INLINE uint64_t enterUniaxialLanes(const Vec3& axis, double nOutside, const double* nO, const double* nE,
                                       const double* const direction[3], const double* const normal[3],
                                       size_t count, double* numbers, size_t stride) {
    if (!uniaxial::mediumChecks(axis, nOutside)) return 0;
    const DoubleTag d;
    const size_t lanes = hn::Lanes(d);
    using Entry = uniaxial::UniaxialEntry<Doubles>;
    uint64_t entered = 0;
    for (size_t first = 0; first < count; first += lanes) {
        auto load = [&](const double* const v[3]) {
            return uniaxial::V3<Doubles>{Doubles::load(v[0] + first), Doubles::load(v[1] + first),
                                         Doubles::load(v[2] + first)};
        };
        Entry e = uniaxial::enterUniaxial(Doubles::load(nO + first), Doubles::load(nE + first), axis,
                                          load(direction), load(normal), nOutside);
        auto met = e.met[0];
        for (int i = 1; i < Entry::kConditions; ++i) met = hn::And(met, e.met[i]);
        uint64_t bits = 0;
        hn::StoreMaskBits(d, met, reinterpret_cast<uint8_t*>(&bits));
        bits &= count - first >= 64 ? ~uint64_t(0) : (uint64_t(1) << (count - first)) - 1;
        if (!bits) continue;
        double* p = numbers + first;
        e.forEachNumber([&](Doubles& v) {
            v.store(p);
            p += stride;
        });
        entered |= bits << first;
    }
    return entered;
}

// A crystal wave incident[j] of crystal {nO[j], nE[j], axis} meeting a facet of unit outward normal[j] from
// inside, the isotropic medium outside of index nOutside, for j < count (nO, nE and normal readable as
// above): for each j whose bit is set in the result (the crystal's reflected waves propagating; the outside
// ones too, or neither), leaveCrystal(...)'s waves as uniaxial::LeavingLane{numbers + j, stride, bit j of
// `evanescent`} reads them (UniaxialLeaving's numbers, number i at numbers[i * stride + j]; stride at least
// count rounded up to a whole vector of doubles); the others are left to leaveCrystal. Only what a lane's
// choice reads is stored, and read back lane by lane.
HWY_INLINE uint64_t leaveUniaxialLanes(const Vec3& axis, double nOutside, const double* nO, const double* nE,
                                       const PlaneWave* const incident[], const double* const normal[3],
                                       size_t count, double* numbers, size_t stride, uint64_t& evanescent) {
    evanescent = 0;
    if (!uniaxial::mediumChecks(axis, nOutside)) return 0;
    const DoubleTag d;
    const size_t lanes = hn::Lanes(d);
    using Leaving = uniaxial::UniaxialLeaving<Doubles>;
    constexpr size_t kLanes = HWY_LANES(double);
    // The incident waves' numbers: wave normal, ray, field, index, ordinary (1) or not (0).
    alignas(64) double wave[11][kLanes];
    uint64_t left = 0;
    for (size_t first = 0; first < count; first += lanes) {
        const size_t here = std::min(lanes, count - first);
        for (size_t k = 0; k < lanes; ++k) {
            const PlaneWave& p = *incident[first + std::min(k, here - 1)];
            const Vec3* v[3] = {&p.waveNormal, &p.ray, &p.field};
            for (int i = 0; i < 3; ++i)
                wave[3 * i][k] = v[i]->x, wave[3 * i + 1][k] = v[i]->y, wave[3 * i + 2][k] = v[i]->z;
            wave[9][k] = p.index;
            wave[10][k] = p.mode == WaveMode::Ordinary ? 1 : 0;
        }
        auto vec = [&](const double* x, const double* y, const double* z) {
            return uniaxial::V3<Doubles>{Doubles::load(x), Doubles::load(y), Doubles::load(z)};
        };
        const uniaxial::LeavingStart<Doubles> start = uniaxial::startLeaving(
            Doubles::load(nO + first), Doubles::load(nE + first), axis, vec(wave[0], wave[1], wave[2]),
            vec(wave[3], wave[4], wave[5]), vec(wave[6], wave[7], wave[8]), Doubles::load(wave[9]),
            Doubles(0.5) < Doubles::load(wave[10]),
            vec(normal[0] + first, normal[1] + first, normal[2] + first), nOutside);
        auto met = start.out.met[0];
        for (int i = 1; i < Leaving::kStartConditions; ++i) met = hn::And(met, start.out.met[i]);
        auto bitsOf = [&](hn::Mask<DoubleTag> m) {
            uint64_t bits = 0;
            hn::StoreMaskBits(d, m, reinterpret_cast<uint8_t*>(&bits));
            return bits & ((uint64_t(1) << here) - 1);
        };
        const Doubles zero(0.0);
        // Each kind of outside wave where a lane has it: its waves in lanes, stored over that kind's lanes.
        uint64_t stored = 0;  // this vector's lanes stored so far
        for (const bool kind : {false, true}) {
            const auto ofKind = hn::And(met, kind ? start.outside2 < zero : zero < start.outside2);
            if (!bitsOf(ofKind)) continue;
            Leaving e = kind ? uniaxial::leaveIntoEvanescent(start) : uniaxial::leaveIntoPropagating(start);
            const auto mine = hn::And(ofKind, e.met[Leaving::kConditions - 1]);
            const uint64_t bits = bitsOf(mine);
            if (!bits) continue;
            double* p = numbers + first;
            e.forEachNumber([&](Doubles& v) {
                (stored ? select(mine, v, Doubles::load(p)) : v).store(p);
                p += stride;
            });
            stored |= bits;
            if (kind) evanescent |= bits << first;
        }
        left |= stored << first;
    }
    return left;
}

// The draws (uniaxial::drawWave) of photons in state `pol` along d (alike for all) whose entries j < count
// enterUniaxialLanes() stored in `numbers` (stride as there), photon j's stream at state[j] (Rng::state(),
// readable as nO is; not advanced): bit j of `reflected` where photon j's draw reflects it, else of
// `ordinary` where it enters as the ordinary wave (the bits of entries not stored are unspecified).
HWY_INLINE void drawEntryLanes(const Polarization& pol, const Vec3f& d, const double* numbers, size_t stride,
                               const uint64_t* state, size_t count, uint64_t& reflected, uint64_t& ordinary) {
    using Entry = uniaxial::UniaxialEntry<double>;
    using Halves = Lanes<HalfTag>;  // floats, one per lane of doubles
    const DoubleTag dd;
    const size_t lanes = hn::Lanes(dd);
    const StokesOf<Halves> stokes{Halves(pol.stokes.s0), Halves(pol.stokes.s1), Halves(pol.stokes.s2),
                                  Halves(pol.stokes.s3)};
    const Vec3Of<Halves> x{Halves(pol.x.x), Halves(pol.x.y), Halves(pol.x.z)};
    const Vec3Of<Halves> dir{Halves(d.x), Halves(d.y), Halves(d.z)};
    const Doubles zero(0.0);
    reflected = 0, ordinary = 0;
    for (size_t first = 0; first < count; first += lanes) {
        auto number = [&](int i) { return Doubles::load(numbers + size_t(i) * stride + first); };
        auto narrow = [&](Doubles v) { return Halves(hn::DemoteTo(HalfTag(), v.v)); };
        // PhotonWalker::drawEntryWave(): the state as a coherency matrix over the incident s (in float), the
        // waves' shares of it (their amplitudes real, as uniaxial::EntryLane gives them), the draw.
        const Vec3Of<Halves> s{narrow(number(0)), narrow(number(1)), narrow(number(2))};
        const CoherencyParts<Doubles> j = coherencyParts<Doubles>(
            rotateFrame(stokes, x, s, dir), [&](Halves v) { return Doubles(hn::PromoteTo(dd, v.v)); });
        auto share = [&](int w) {
            const int at = Entry::kFluxes + 3 * w;
            return shareOfParts(number(at), number(at + 1), zero, number(at + 2), zero, j.ss, j.pp, j.spRe,
                                j.spIm);
        };
        const uniaxial::WaveDraw<Doubles> draw =
            uniaxial::drawWave(nextUniformOf(state + first), share(0), share(1), share(2), share(3));
        uint64_t reflectedBits = 0, ordinaryBits = 0;
        hn::StoreMaskBits(dd, draw.pair, reinterpret_cast<uint8_t*>(&reflectedBits));
        hn::StoreMaskBits(dd, draw.ordinary, reinterpret_cast<uint8_t*>(&ordinaryBits));
        reflected |= reflectedBits << first, ordinary |= ordinaryBits << first;
    }
}

// The draws (uniaxial::drawWave) of the photons whose leavings j < count leaveUniaxialLanes() stored in
// `numbers` (stride as there), photon j's stream at state[j] (Rng::state(), readable as nO is; not advanced):
// bit j of `out` where photon j's draw takes it out, else of `ordinary` where it reflects as the ordinary
// wave (the bits of leavings not stored are unspecified).
HWY_INLINE void drawLeavingLanes(const double* numbers, size_t stride, const uint64_t* state, size_t count,
                                 uint64_t& out, uint64_t& ordinary) {
    const DoubleTag d;
    const size_t lanes = hn::Lanes(d);
    out = 0, ordinary = 0;
    for (size_t first = 0; first < count; first += lanes) {
        auto share = [&](int i) { return Doubles::load(numbers + size_t(i) * stride + first); };
        // Stored reflected o and e, then transmitted s and p: the pair is the transmitted one.
        const uniaxial::WaveDraw<Doubles> draw =
            uniaxial::drawWave(nextUniformOf(state + first), share(2), share(3), share(0), share(1));
        uint64_t outBits = 0, ordinaryBits = 0;
        hn::StoreMaskBits(d, draw.pair, reinterpret_cast<uint8_t*>(&outBits));
        hn::StoreMaskBits(d, draw.ordinary, reinterpret_cast<uint8_t*>(&ordinaryBits));
        out |= outBits << first, ordinary |= ordinaryBits << first;
    }
}

#endif  // HWY_TARGET != HWY_SCALAR
}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#endif
