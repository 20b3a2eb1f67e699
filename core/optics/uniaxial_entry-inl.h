// Inside core/ (per SIMD target, included after hwy/foreach_target.h or hwy/highway.h): the entry into a
// uniaxial crystal (optics/uniaxial_entry.h) for several photons at once, lanes of doubles, with the bits of
// enterCrystal() for each.
#if defined(FACETLIGHT_UNIAXIAL_ENTRY_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACETLIGHT_UNIAXIAL_ENTRY_INL_H_
#undef FACETLIGHT_UNIAXIAL_ENTRY_INL_H_
#else
#define FACETLIGHT_UNIAXIAL_ENTRY_INL_H_
#endif

#include <algorithm>
#include <cstdint>

#include "hwy/highway.h"
#include "optics/uniaxial_entry.h"
#include "util/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {
#if HWY_TARGET != HWY_SCALAR

// Light from the isotropic medium of index nOutside entering crystals {nO[j], nE[j], axis} along unit
// direction[j] through facets of unit outward normal[j], for j < count (each array readable up to count
// rounded up to a whole vector of doubles): out[j] = enterCrystal(...) for each j whose bit is set in the
// result (every wave propagating, no degenerate direction); the others are left to enterCrystal.
HWY_INLINE uint64_t enterUniaxialLanes(const Vec3& axis, double nOutside, const double* nO, const double* nE,
                                       const double* const direction[3], const double* const normal[3],
                                       size_t count, InterfaceWaves* out) {
    if (!uniaxial::mediumChecks(axis, nOutside)) return 0;
    const DoubleTag d;
    const size_t lanes = hn::Lanes(d);
    using Entry = uniaxial::UniaxialEntry<Doubles>;
    alignas(64) double numbers[Entry::kNumbers][HWY_LANES(double)];
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
        int i = 0;
        e.forEachNumber([&](Doubles& v) { v.store(numbers[i++]); });
        for (uint64_t b = bits; b; b &= b - 1) {
            const int k = __builtin_ctzll(b);
            uniaxial::UniaxialEntry<double> one;
            int j = 0;
            one.forEachNumber([&](double& v) { v = numbers[j++][k]; });
            uniaxial::putInterfaceWaves(one, out[first + k]);
        }
        entered |= bits << first;
    }
    return entered;
}

#endif  // HWY_TARGET != HWY_SCALAR
}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#endif
