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

namespace facetlight {

struct Stokes {
    float s0 = 1, s1 = 0, s2 = 0, s3 = 0;  // unpolarised by default

    // Linear light at angle psi (radians) from the frame's x toward its y.
    static Stokes linear(double psi) { return {1, float(std::cos(2 * psi)), float(std::sin(2 * psi)), 0}; }
    float degree() const { return std::sqrt(s1 * s1 + s2 * s2 + s3 * s3) / s0; }
};

// A photon's polarisation: its Stokes vector and the frame's x (unit, across the direction of travel).
struct Polarization {
    Stokes stokes;
    Vec3f x;
};

// The state referred to another x across the same direction of travel d: the frame turned by phi, with
// cos phi = x.x' and sin phi = (x cross x').d (Chandrasekhar, Radiative Transfer, sec. 15: the rotation
// matrix L(phi)).
inline Stokes rotateFrame(const Stokes& s, const Vec3f& x, const Vec3f& newX, const Vec3f& d) {
    const float c = dot(x, newX), sn = dot(cross(x, newX), d);
    const float c2 = c * c - sn * sn, s2 = 2 * sn * c;
    return {s.s0, c2 * s.s1 + s2 * s.s2, c2 * s.s2 - s2 * s.s1, s.s3};
}

// The Mueller matrix of a wave's passage through a facet in the s-p frame: diattenuation (a, b) and
// retardation (c, e), from the amplitude coefficients ts, tp of that wave (already scaled so that |t|^2 is
// its energy share): a = (|ts|^2 + |tp|^2) / 2, b = (|ts|^2 - |tp|^2) / 2, c + i e = ts conj(tp).
struct FacetMueller {
    float a = 1, b = 0, c = 1, e = 0;

    // The share of a state's energy this wave takes (S0 = 1).
    float share(const Stokes& s) const { return a * s.s0 + b * s.s1; }
    // The state it leaves with, back to S0 = 1.
    Stokes apply(const Stokes& s) const {
        const float s0 = a * s.s0 + b * s.s1;
        const float inv = 1.0f / s0;
        return {1.0f, (b * s.s0 + a * s.s1) * inv, (c * s.s2 + e * s.s3) * inv, (c * s.s3 - e * s.s2) * inv};
    }
};

// The reflected and refracted waves at a facet between isotropic media, for light going from index n1 to
// n2 (eta = n1 / n2) at cos(incidence) cosI in [0, 1].
struct FacetWaves {
    FacetMueller reflected, refracted;  // refracted is unused under total internal reflection
    float cosT = 0;                     // 0 under total internal reflection
    bool totalInternal = false;
};

inline FacetWaves facetWaves(float cosI, float eta) {
    FacetWaves w;
    const float sin2T = eta * eta * std::max(0.0f, 1 - cosI * cosI);
    if (sin2T >= 1) {
        // cos t = i b: rs = (a - i b) / (a + i b) with a = eta cos i, rp = (cos i - i eta b) / (cos i + i eta
        // b) (both divided by n2); |rs| = |rp| = 1.
        const float b = std::sqrt(sin2T - 1), a = eta * cosI, g = eta * b;
        const float sRe = (a * a - b * b) / (a * a + b * b), sIm = -2 * a * b / (a * a + b * b);
        const float pRe = (cosI * cosI - g * g) / (cosI * cosI + g * g),
                    pIm = -2 * cosI * g / (cosI * cosI + g * g);
        w.reflected = {1, 0, sRe * pRe + sIm * pIm, sIm * pRe - sRe * pIm};  // rs conj(rp)
        w.totalInternal = true;
        return w;
    }
    const float cosT = std::sqrt(1 - sin2T);
    const float rs = (eta * cosI - cosT) / (eta * cosI + cosT);
    const float rp = (cosI - eta * cosT) / (cosI + eta * cosT);
    const float Rs = rs * rs, Rp = rp * rp;
    w.reflected = {(Rs + Rp) / 2, (Rs - Rp) / 2, rs * rp, 0};
    // Energy shares 1 - R; ts and tp are real and positive, so their product is sqrt(Ts Tp).
    const float Ts = 1 - Rs, Tp = 1 - Rp;
    w.refracted = {(Ts + Tp) / 2, (Ts - Tp) / 2, std::sqrt(Ts * Tp), 0};
    w.cosT = cosT;
    return w;
}

// The s direction of a facet of normal `normal` met along d: across the plane of incidence. At normal
// incidence every direction across d is one, and the photon's own x is kept.
inline Vec3f sDirection(const Vec3f& d, const Vec3f& normal, const Vec3f& x) {
    const Vec3f s = cross(d, normal);
    const float len2 = dot(s, s);
    return len2 > 1e-12f ? s * (1.0f / std::sqrt(len2)) : x;
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
