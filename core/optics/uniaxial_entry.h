#pragma once
// Light from the isotropic medium entering a uniaxial crystal where every wave propagates (the entry from
// air, docs/optics.md "Birefringence: waves at an interface"), written once over the number type: double for
// enterCrystal() (optics/birefringence.cpp), the Doubles of util/lanes-inl.h for a packet's lanes
// (optics/uniaxial_entry-inl.h), so that both give the same bits. It computes what enterCrystal's
// all-real case (`enterWith<double, double>`) computes, by the same operations in the same order (Vec3's
// dot, cross, length and normalize written out over T; its branches between two vectors as selects of
// both); its other branches become conditions: an incidence where one fails (an evanescent wave, a singular
// system, input enterCrystal refuses) is left to enterCrystal's general code.
#include <cmath>

#include "optics/birefringence.h"

namespace facetlight {
namespace uniaxial {

// Inlined into per-target callers (util/lanes-inl.h): functions, and lambdas.
#define FACETLIGHT_AI [[gnu::always_inline]] inline
#define FACETLIGHT_AL __attribute__((always_inline))

// Vec3 over a number type, with Vec3's rounding.
template <class T>
struct V3 {
    T x, y, z;
};
template <class T>
FACETLIGHT_AI V3<T> operator+(const V3<T>& a, const V3<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <class T>
FACETLIGHT_AI V3<T> operator-(const V3<T>& a, const V3<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <class T>
FACETLIGHT_AI V3<T> operator-(const V3<T>& a) {
    return {-a.x, -a.y, -a.z};
}
template <class T>
FACETLIGHT_AI V3<T> operator*(const V3<T>& a, T s) {
    return {a.x * s, a.y * s, a.z * s};
}
template <class T>
FACETLIGHT_AI V3<T> operator/(const V3<T>& a, T s) {
    return {a.x / s, a.y / s, a.z / s};
}
template <class T>
FACETLIGHT_AI T dot(const V3<T>& a, const V3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class T>
FACETLIGHT_AI V3<T> cross(const V3<T>& a, const V3<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class T>
FACETLIGHT_AI T length(const V3<T>& a) {
    using std::sqrt;
    return sqrt(dot(a, a));
}
template <class T>
FACETLIGHT_AI V3<T> lift(const Vec3& v) {
    return {T(v.x), T(v.y), T(v.z)};
}
// The lane-wise `mask ? a : b` for doubles and vectors (util/lanes-inl.h has the lanes').
FACETLIGHT_AI double select(bool mask, double a, double b) {
    return mask ? a : b;
}
template <class T, class Mask>
FACETLIGHT_AI V3<T> select(Mask mask, const V3<T>& a, const V3<T>& b) {
    return {select(mask, a.x, b.x), select(mask, a.y, b.y), select(mask, a.z, b.z)};
}
// birefringence.cpp's perpendicularTo (Duff et al. 2017): a unit vector perpendicular to unit n.
template <class T>
FACETLIGHT_AI V3<T> perpendicularTo(const V3<T>& n) {
    using std::copysign;
    const T sign = copysign(T(1.0), n.z);
    const T a = T(-1.0) / (sign + n.z);
    return {T(1.0) + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x};
}
// eps v for eps = n_o^2 I + (n_e^2 - n_o^2) c c^T.
template <class T>
FACETLIGHT_AI V3<T> epsilonTimes(T nO, T nE, const V3<T>& c, const V3<T>& v) {
    return v * (nO * nO) + c * (dot(c, v) * (nE * nE - nO * nO));
}

// One propagating wave as PlaneWave and OutgoingWave hold it (ray = waveNormal but for the extraordinary
// wave; amplitudes real).
template <class T>
struct EntryWave {
    V3<T> waveNormal, ray, field;
    T index, amplitude[2], fluxRatio, share[2];
};

// The waves of enterCrystal() in the all-real case: incident s and p (one wave normal), reflected s and p,
// transmitted ordinary and extraordinary. `met` holds the conditions under which these are enterCrystal's
// waves, each true (a bool, or a lane mask) where it holds.
template <class T>
struct UniaxialEntry {
    using Mask = decltype(T{} < T{});
    static constexpr int kConditions = 7;
    static constexpr int kNumbers = 3 * 3 + 1 + 4 * (3 * 3 + 6);  // forEachNumber's
    Mask met[kConditions];
    V3<T> incidentNormal, incidentS, incidentP;
    T incidentIndex;
    EntryWave<T> reflected[2], transmitted[2];

    // f(x) for each number, in a fixed order (to move the lanes' results into scalar ones).
    template <class F>
    FACETLIGHT_AI void forEachNumber(F&& f) {
        for (V3<T>* v : {&incidentNormal, &incidentS, &incidentP}) f(v->x), f(v->y), f(v->z);
        f(incidentIndex);
        for (EntryWave<T>* w : {&reflected[0], &reflected[1], &transmitted[0], &transmitted[1]}) {
            for (V3<T>* v : {&w->waveNormal, &w->ray, &w->field}) f(v->x), f(v->y), f(v->z);
            f(w->index), f(w->amplitude[0]), f(w->amplitude[1]), f(w->fluxRatio), f(w->share[0]),
                f(w->share[1]);
        }
    }
};

// The medium's part of enterCrystal's check that is the same for every lane: a unit axis and a positive
// outside index.
inline bool mediumChecks(const Vec3& axis, double nOutside) {
    return std::fabs(dot(axis, axis) - 1) < 1e-9 && nOutside > 0;
}

// enterCrystal(UniaxialMedium{nO, nE, axis}, direction, outwardNormal, nOutside) where every wave
// propagates; see birefringence.cpp for each step's why (the same names).
template <class T>
FACETLIGHT_AI UniaxialEntry<T> enterUniaxial(T nO, T nE, const Vec3& axis, const V3<T>& direction,
                                             const V3<T>& outwardNormal, double nOutside) {
    using std::sqrt;
    // Below this |k x c| / |k| a wave normal counts as along the axis (birefringence.cpp's kAlongAxis).
    constexpr double kAlongAxis = 1e-9;
    const T zero(0.0), n(nOutside), alongAxis2(kAlongAxis * kAlongAxis);
    UniaxialEntry<T> e;
    const V3<T> c = lift<T>(axis);
    auto epsilonTimes = [&](const V3<T>& v) FACETLIGHT_AL { return uniaxial::epsilonTimes(nO, nE, c, v); };

    const V3<T> N = -outwardNormal;
    const T cosI = dot(direction, N);
    const V3<T> kt = (direction - N * cosI) * n;
    // sDirection: any perpendicular to N at normal incidence.
    const V3<T> sCross = cross(kt, N);
    const T sLength = length(sCross);
    const V3<T> s = select(T(1e-12) < sLength, sCross / sLength, perpendicularTo(N));
    // ordinaryField's fallback along the axis: the part of s across it.
    const V3<T> acrossAxis = s - c * dot(c, s);
    // extraordinaryRoots
    const V3<T> epsN = epsilonTimes(N), epsKt = epsilonTimes(kt);
    const T a = dot(N, epsN), b = dot(kt, epsN);
    const T cq = dot(kt, epsKt) - nO * nO * nE * nE;
    const T discriminant = b * b - a * cq;
    const T kt2 = dot(kt, kt);
    // ordinaryInterfaceWave, side +1
    const T q2 = nO * nO - kt2;
    const T qO = sqrt(q2);
    const V3<T> kO = kt + N * qO;
    const V3<T> eO = cross(kO, c);
    const V3<T> fieldO = select(alongAxis2 * dot(kO, kO) < dot(eO, eO), eO, acrossAxis);
    // extraordinaryInterfaceWave, side +1
    const T root = sqrt(discriminant);
    const T qE = (-b + root) / a;
    const V3<T> kE = kt + N * qE;
    const T rayNormalE = root / length(epsKt + epsN * qE);
    const V3<T> dE = c * dot(kE, kE) - kE * dot(kE, c);
    const T io = T(1.0) / (nO * nO), ie = T(1.0) / (nE * nE);
    // extraordinaryField: E = eps^-1 D, or along the axis k x E_o.
    const V3<T> eOE = cross(kE, c);
    const V3<T> fieldOE = select(alongAxis2 * dot(kE, kE) < dot(eOE, eOE), eOE, acrossAxis);
    const V3<T> fieldE = select(alongAxis2 * dot(kE, kE) * dot(kE, kE) < dot(dE, dE),
                                dE * io + c * (dot(c, dE) * (ie - io)), cross(kE, fieldOE));
    // isotropicWave: incident (+1) and reflected (-1) s and p
    const T outside2 = n * n - kt2;
    const T qI = sqrt(outside2), qR = -qI;
    const V3<T> kI = kt + N * qI, kR = kt + N * qR;
    const T inverseN(1 / nOutside);
    const V3<T> fieldIP = cross(kI, s) * inverseN, fieldRP = cross(kR, s) * inverseN;

    e.met[0] = zero < cosI;
    e.met[1] = zero < q2;
    e.met[2] = zero < discriminant;
    e.met[3] = zero < outside2;
    e.met[4] = zero < nO;
    e.met[5] = zero < nE;

    // matchFields: the crystal's waves transmitted, the isotropic ones (s, p) reflected.
    const V3<T> t2 = cross(N, s);
    auto tangential = [&](const V3<T>& k, const V3<T>& field, T out[4]) FACETLIGHT_AL {
        const V3<T> h = cross(k, field);
        out[0] = dot(field, s), out[1] = dot(field, t2), out[2] = dot(h, s), out[3] = dot(h, t2);
    };
    T cO[4], cE[4];
    tangential(kO, fieldO, cO);
    tangential(kE, fieldE, cE);
    const T q = qR, g = q / (n * n);
    const T m00 = cO[3] - q * cO[0], m01 = cE[3] - q * cE[0];
    const T m10 = cO[1] + g * cO[2], m11 = cE[1] + g * cE[2];
    const T det = m00 * m11 - m01 * m10;
    // The singular system enterCrystal refuses; the same test (std::norm of a double squares it).
    e.met[6] = zero < det * det;
    T x[4][2];  // reflected s, p, transmitted ordinary, extraordinary, per incident s, p
    const V3<T> incidentField[2] = {s, fieldIP};
    for (int i = 0; i < 2; ++i) {
        T bt[4];
        tangential(kI, incidentField[i], bt);
        const T r0 = bt[3] - q * bt[0], r1 = bt[1] + g * bt[2];
        const T u0 = (r0 * m11 - m01 * r1) / det, u1 = (m00 * r1 - m10 * r0) / det;
        x[2][i] = u0;
        x[3][i] = u1;
        x[0][i] = -(bt[0] - cO[0] * u0 - cE[0] * u1);
        x[1][i] = -(cO[2] * u0 + cE[2] * u1 - bt[2]) / n;
    }
    e.incidentIndex = length(kI);
    e.incidentNormal = kI / e.incidentIndex;
    e.incidentS = s / length(s);
    e.incidentP = fieldIP / length(fieldIP);
    const T incidentFlux = e.incidentIndex * (qI / n);

    // fill(): a wave's unit field, plane wave, flux ratio (normalFlux over incidentFlux) and amplitudes.
    auto fill = [&](EntryWave<T>& w, const V3<T>& k, const V3<T>& field, const T flux[2], bool negative,
                    bool extraordinary, T rayNormal) FACETLIGHT_AL {
        const T fieldScale = length(field);
        w.field = field / fieldScale;
        w.index = length(k);
        w.waveNormal = k / w.index;
        w.ray = extraordinary ? epsilonTimes(k) : w.waveNormal;
        if (extraordinary) w.ray = w.ray / length(w.ray);
        const T across = extraordinary ? length(w.waveNormal - w.field * dot(w.waveNormal, w.field)) : T(1.0);
        const T normalFlux = w.index * across * rayNormal;
        w.fluxRatio = (negative ? -normalFlux : normalFlux) / incidentFlux;
        for (int i = 0; i < 2; ++i) {
            w.amplitude[i] = flux[i] * fieldScale;
            w.share[i] = w.fluxRatio * (w.amplitude[i] * w.amplitude[i] + zero * zero);
        }
    };
    fill(e.transmitted[0], kO, fieldO, x[2], false, false, qO / nO);
    fill(e.transmitted[1], kE, fieldE, x[3], false, true, rayNormalE);
    fill(e.reflected[0], kR, s, x[0], true, false, qR / n);
    fill(e.reflected[1], kR, fieldRP, x[1], true, false, qR / n);
    return e;
}

// enterCrystal's InterfaceWaves, into `out`, of a scalar entry whose conditions are all met.
inline void putInterfaceWaves(const UniaxialEntry<double>& e, InterfaceWaves& out) {
    auto vec = [](const V3<double>& v) { return Vec3{v.x, v.y, v.z}; };
    auto put = [&](OutgoingWave& o, WaveMode mode, const EntryWave<double>& w) {
        o.wave = {mode, vec(w.waveNormal), vec(w.ray), vec(w.field), w.index};
        o.propagating = true;
        o.fluxRatio = w.fluxRatio;
        for (int i = 0; i < 2; ++i) o.amplitude[i] = Complex(w.amplitude[i], 0.0), o.share[i] = w.share[i];
    };
    out.incidentCount = 2;
    const Vec3 incidentNormal = vec(e.incidentNormal);
    out.incident[0] = {WaveMode::S, incidentNormal, incidentNormal, vec(e.incidentS), e.incidentIndex};
    out.incident[1] = {WaveMode::P, incidentNormal, incidentNormal, vec(e.incidentP), e.incidentIndex};
    put(out.reflected[0], WaveMode::S, e.reflected[0]);
    put(out.reflected[1], WaveMode::P, e.reflected[1]);
    put(out.transmitted[0], WaveMode::Ordinary, e.transmitted[0]);
    put(out.transmitted[1], WaveMode::Extraordinary, e.transmitted[1]);
}

#undef FACETLIGHT_AI
#undef FACETLIGHT_AL

}  // namespace uniaxial
}  // namespace facetlight
