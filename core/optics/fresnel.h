#pragma once
// Unpolarised Fresnel reflectance at an interface (docs/optics.md), for one ray or for a packet of rays:
// written once over the number type so that both give the same bits; and the reflected and refracted
// directions of one ray.
#include <cmath>

#include "geometry/geometry.h"

namespace facetlight {

inline float select(bool mask, float a, float b) {
    return mask ? a : b;
}

// For rays with cos(incidence) cosI in [0, 1] going from index n1 to n2, eta = n1 / n2. Mask is bool for a
// float and the lane mask for lanes of floats (util/lanes-inl.h).
template <class F, class Mask = decltype(F{} < F{})>
struct FresnelTerms {
    Mask totalInternal;
    F reflectance;  // 1 under total internal reflection
    F cosT;         // cos of the refraction angle; 0 under total internal reflection
};

// Always inlined, so that lanes of a SIMD target are computed with that target's instructions
// (util/lanes-inl.h).
template <class F>
[[gnu::always_inline]] inline FresnelTerms<F> fresnelTerms(F cosI, F eta) {
    using std::sqrt;
    const F zero(0.0f), one(1.0f), two(2.0f);
    const F cos2I = one - cosI * cosI;
    const F sin2T = eta * eta * select(cos2I < zero, zero, cos2I);
    const auto totalInternal = sin2T >= one;
    const F cosT = select(totalInternal, zero, sqrt(select(totalInternal, zero, one - sin2T)));
    // Rs and Rp with numerator and denominator divided by n2, over one common denominator.
    const F sNum = eta * cosI - cosT, sDen = eta * cosI + cosT;
    const F pNum = eta * cosT - cosI, pDen = eta * cosT + cosI;
    const F r = (sNum * sNum * pDen * pDen + pNum * pNum * sDen * sDen) / (two * sDen * sDen * pDen * pDen);
    return {totalInternal, select(totalInternal, one, r), cosT};
}

using FresnelResult = FresnelTerms<float>;
inline FresnelResult fresnel(float cosI, float eta) {
    return fresnelTerms(cosI, eta);
}

// A ray from outside at cos(incidence) cosI off a facet of outward normal `normal`, and into it with
// eta = 1 / n (Snell's law).
inline Vec3f reflectOff(const Vec3f& d, const Vec3f& normal, float cosI) {
    return d + normal * (2 * cosI);
}
inline Vec3f refractIn(const Vec3f& d, const Vec3f& normal, float eta, float cosI, float cosT) {
    return normalize(d * eta + normal * (eta * cosI - cosT));
}
// Out of the stone (index n) into air through a facet of outward normal `normal` (Snell's law).
inline Vec3f refractOut(const Vec3f& d, const Vec3f& normal, float n, float cosI, float cosT) {
    return normalize(d * n - normal * (n * cosI - cosT));
}

}  // namespace facetlight
