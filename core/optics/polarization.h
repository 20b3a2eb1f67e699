#pragma once
// Polarised light as a Stokes vector, and what a facet between two isotropic media does to it
// (docs/optics.md, "Polarisation"). A photon carries its state as Stokes parameters (not a Jones vector)
// because sources are unpolarised and light that has met a few facets is partly polarised: a Stokes vector
// holds both, and the reflect-or-refract choice takes the state's own reflectance with no extra random draw.
//
// Conventions (Born & Wolf, Principles of Optics, 7th ed., sec. 1.4 and 1.5; Hecht, Optics, 8.13):
// - A state is referred to a unit vector x across the direction of travel d, with y = d x x, so that
//   (x, y, d) is right-handed. S1 = Ix - Iy, S2 = I(+45 deg) - I(-45 deg), S3 = 2 Im(conj(Ex) Ey): linear
//   light at angle psi from x toward y has S1 = cos 2psi, S2 = sin 2psi.
// - At a facet, x is the s direction (across the plane of incidence, s = d x normal, normalised) and each
//   wave's p direction is k x s, for the incident, reflected and refracted waves alike. With fields
//   exp(i(k.r - wt)) the amplitude coefficients are then
//     rs = (n1 cos i - n2 cos t) / (n1 cos i + n2 cos t),  rp = (n2 cos i - n1 cos t) / (n2 cos i + n1 cos
//     t),
//   and past the critical angle cos t = i sqrt(sin^2 t - 1) (the wave beyond decays), |rs| = |rp| = 1 and
//   only the phases differ (total internal reflection's retardation, Born & Wolf sec. 1.5.4).
// - The photon's state is kept with S0 = 1: the random choice carries the energy, so tallies stay integers.
#include <algorithm>
#include <cmath>

#include "geometry/ray.h"
#include "optics/fresnel.h"

namespace facetlight {

// The arithmetic of this file is written once over the number type F: a float for one photon, lanes of
// floats for the packet walk (util/lanes-inl.h), so that both compute the same bits. Each function is always
// inlined, so that lanes are computed with the caller's SIMD target's instructions.

// Three components of number type F, with Vec3f's rounding: dot is (ax bx + ay by) + az bz.
template <class F>
struct Vec3Of {
    F x, y, z;
};
inline Vec3Of<float> lanewise(const Vec3f& v) {
    return {v.x, v.y, v.z};
}
inline Vec3f toVec3f(const Vec3Of<float>& v) {
    return {v.x, v.y, v.z};
}
template <class F>
[[gnu::always_inline]] inline F dot(const Vec3Of<F>& a, const Vec3Of<F>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class F>
[[gnu::always_inline]] inline Vec3Of<F> cross(const Vec3Of<F>& a, const Vec3Of<F>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <class F>
struct StokesOf {
    F s0 = F(1.0f), s1 = F(0.0f), s2 = F(0.0f), s3 = F(0.0f);  // unpolarised by default

    // Linear light at angle psi (radians) from the frame's x toward its y.
    static StokesOf linear(double psi) { return {1, float(std::cos(2 * psi)), float(std::sin(2 * psi)), 0}; }
    F degree() const { return std::sqrt(s1 * s1 + s2 * s2 + s3 * s3) / s0; }
};
using Stokes = StokesOf<float>;

// A photon's polarisation: its Stokes vector and the frame's x (unit, across the direction of travel).
struct Polarization {
    Stokes stokes;
    Vec3f x;
};

// The state referred to another x across the same direction of travel d: the frame turned by phi, with
// cos phi = x.x' and sin phi = (x cross x').d (Chandrasekhar, Radiative Transfer, sec. 15: the rotation
// matrix L(phi)).
template <class F>
[[gnu::always_inline]] inline StokesOf<F> rotateFrame(const StokesOf<F>& s, const Vec3Of<F>& x,
                                                      const Vec3Of<F>& newX, const Vec3Of<F>& d) {
    const F c = dot(x, newX), sn = dot(cross(x, newX), d);
    const F c2 = c * c - sn * sn, s2 = F(2.0f) * sn * c;
    return {s.s0, c2 * s.s1 + s2 * s.s2, c2 * s.s2 - s2 * s.s1, s.s3};
}
inline Stokes rotateFrame(const Stokes& s, const Vec3f& x, const Vec3f& newX, const Vec3f& d) {
    return rotateFrame(s, lanewise(x), lanewise(newX), lanewise(d));
}

// The Mueller matrix of a wave's passage through a facet in the s-p frame: diattenuation (a, b) and
// retardation (c, e), from the amplitude coefficients ts, tp of that wave (already scaled so that |t|^2 is
// its energy share): a = (|ts|^2 + |tp|^2) / 2, b = (|ts|^2 - |tp|^2) / 2, c + i e = ts conj(tp).
template <class F>
struct FacetMuellerOf {
    F a = F(1.0f), b = F(0.0f), c = F(1.0f), e = F(0.0f);

    // The share of a state's energy this wave takes (S0 = 1).
    [[gnu::always_inline]] inline F share(const StokesOf<F>& s) const { return a * s.s0 + b * s.s1; }
    // The state it leaves with, back to S0 = 1.
    [[gnu::always_inline]] inline StokesOf<F> apply(const StokesOf<F>& s) const {
        const F s0 = a * s.s0 + b * s.s1;
        const F inv = F(1.0f) / s0;
        return {F(1.0f), (b * s.s0 + a * s.s1) * inv, (c * s.s2 + e * s.s3) * inv,
                (c * s.s3 - e * s.s2) * inv};
    }
};
using FacetMueller = FacetMuellerOf<float>;

// The reflected and refracted waves at a facet between isotropic media, for light going from index n1 to
// n2 (eta = n1 / n2) at cos(incidence) cosI in [0, 1]. Mask is bool for a float and the lane mask for lanes.
template <class F, class Mask = decltype(F{} < F{})>
struct FacetWavesOf {
    FacetMuellerOf<F> reflected, refracted;  // refracted is unused under total internal reflection
    F cosT;                                  // 0 under total internal reflection
    Mask totalInternal;
};
using FacetWaves = FacetWavesOf<float>;

// Both cases are worked out and the one that holds is selected, as lanes must; with a division or two
// where the formulas have eight, since divisions are what a packet's step waits on.
template <class F>
[[gnu::always_inline]] inline FacetWavesOf<F> facetWaves(F cosI, F eta) {
    using std::sqrt;
    const F zero(0.0f), one(1.0f), two(2.0f), half(0.5f);
    const F cos2I = one - cosI * cosI;
    const F sin2T = eta * eta * select(cos2I < zero, zero, cos2I);
    const auto totalInternal = sin2T >= one;
    // Total internal reflection: cos t = i b, so (dividing by n2) rs = (a - i b) / (a + i b) with a = eta cos
    // i and rp = (cos i - i g) / (cos i + i g) with g = eta b; |rs| = |rp| = 1, and rs conj(rp) = u / conj(u)
    // = u^2 / |u|^2 with u = (a - i b)(cos i + i g).
    const F b = sqrt(select(totalInternal, sin2T - one, zero)), a = eta * cosI, g = eta * b;
    const F uRe = a * cosI + b * g, uIm = a * g - b * cosI;
    const F invU2 = one / (uRe * uRe + uIm * uIm);
    // Otherwise rs and rp are real, over one common denominator, and the energy shares 1 - R; ts and tp are
    // real and positive, so their product is sqrt(Ts Tp).
    const F cosT = sqrt(select(totalInternal, zero, one - sin2T));
    const F sNum = eta * cosI - cosT, sDen = eta * cosI + cosT;
    const F pNum = cosI - eta * cosT, pDen = cosI + eta * cosT;
    const F invDen = one / (sDen * pDen);
    const F rs = sNum * pDen * invDen, rp = pNum * sDen * invDen;
    const F Rs = rs * rs, Rp = rp * rp, Ts = one - Rs, Tp = one - Rp;
    return {{select(totalInternal, one, (Rs + Rp) * half), select(totalInternal, zero, (Rs - Rp) * half),
             select(totalInternal, (uRe * uRe - uIm * uIm) * invU2, rs * rp),  // rs conj(rp)
             select(totalInternal, two * uRe * uIm * invU2, zero)},
            {(Ts + Tp) * half, (Ts - Tp) * half, sqrt(Ts * Tp), zero},
            cosT,
            totalInternal};
}

// The s direction of a facet of normal `normal` met along d: across the plane of incidence. At normal
// incidence every direction across d is one, and the photon's own x is kept.
template <class F>
[[gnu::always_inline]] inline Vec3Of<F> sDirection(const Vec3Of<F>& d, const Vec3Of<F>& normal,
                                                   const Vec3Of<F>& x) {
    using std::sqrt;
    const Vec3Of<F> s = cross(d, normal);
    const F len2 = dot(s, s);
    const auto across = F(1e-12f) < len2;
    const F inv = F(1.0f) / sqrt(len2);
    return {select(across, s.x * inv, x.x), select(across, s.y * inv, x.y), select(across, s.z * inv, x.z)};
}
inline Vec3f sDirection(const Vec3f& d, const Vec3f& normal, const Vec3f& x) {
    return toVec3f(sDirection(lanewise(d), lanewise(normal), lanewise(x)));
}

// A photon along d with state `stokes` in the frame of x meets a facet of normal `normal` at cos(incidence)
// cosI, going from index n1 to n2 (eta = n1 / n2): the facet's s direction (the x of the waves it leaves
// as), the state referred to it, and the waves.
template <class F>
struct FacetMeeting {
    Vec3Of<F> s;
    StokesOf<F> stokes;
    FacetWavesOf<F> waves;
};
template <class F>
[[gnu::always_inline]] inline FacetMeeting<F> meetFacet(const StokesOf<F>& stokes, const Vec3Of<F>& x,
                                                        const Vec3Of<F>& d, const Vec3Of<F>& normal, F cosI,
                                                        F eta) {
    const Vec3Of<F> s = sDirection(d, normal, x);
    return {s, rotateFrame(stokes, x, s, d), facetWaves(cosI, eta)};
}
inline FacetMeeting<float> meetFacet(const Polarization& pol, const Vec3f& d, const Vec3f& normal, float cosI,
                                     float eta) {
    return meetFacet(pol.stokes, lanewise(pol.x), lanewise(d), lanewise(normal), cosI, eta);
}

// Any unit vector across d: the frame's x for light that starts unpolarised or is referred to `hint` (the
// stone's x axis, or its y where d runs along x).
inline Vec3f frameAcross(const Vec3f& d, const Vec3f& hint) {
    Vec3f x = hint - d * dot(hint, d);
    if (dot(x, x) < 1e-6f) {
        const Vec3f other = std::abs(d.x) < 0.9f ? Vec3f(1, 0, 0) : Vec3f(0, 1, 0);
        x = other - d * dot(other, d);
    }
    return normalize(x);
}

// The share of a state an ideal linear analyser passes whose axis is `axis` (across d): Malus's law for
// polarised light, one half for unpolarised.
inline float analyserShare(const Polarization& p, const Vec3f& d, const Vec3f& axis) {
    const Stokes s = rotateFrame(p.stokes, p.x, axis, d);
    return 0.5f * (s.s0 + s.s1);
}

}  // namespace facetlight
