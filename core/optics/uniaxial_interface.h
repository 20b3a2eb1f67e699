#pragma once
// The interface between a uniaxial crystal and the isotropic medium (docs/optics.md "Birefringence: waves at
// an interface") in its common cases, written once over the number type: double for enterCrystal() and
// leaveCrystal() (optics/birefringence.cpp), the Doubles of util/lanes-inl.h for a packet's lanes
// (optics/uniaxial_interface-inl.h), so that both give the same bits. The cases: light entering where every
// wave propagates (the entry from air), and a crystal wave leaving where both of the crystal's reflected
// waves propagate, the outside ones too or neither (total internal reflection). Each computes what
// birefringence.cpp's general code computes there, by the same operations in the same order (Vec3's dot,
// cross, length and normalize written out over T; std::complex's textbook products and quotients written out
// where the outside waves are evanescent, their q purely imaginary); its branches between two vectors as
// selects of both, its other branches as conditions: an interface where one fails (a crystal wave evanescent,
// a singular system, input birefringence.cpp refuses) is left to the general code.
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

// The crystal's two waves of tangential kt on one side of a facet (`side` +1 along N, -1 against it), with
// what they are found from: birefringence.cpp's sDirection, extraordinaryRoots, ordinaryInterfaceWave and
// extraordinaryInterfaceWave (the same names there).
template <class T>
struct CrystalWavePair {
    V3<T> s, epsN, epsKt;
    T a, b, discriminant, kt2, q2, qO, root, qE, rayNormalE;
    V3<T> kO, fieldO, kE, fieldE;
};
template <class T>
FACETLIGHT_AI CrystalWavePair<T> crystalWavePair(T nO, T nE, const V3<T>& c, const V3<T>& kt, const V3<T>& N,
                                                 double side) {
    using std::sqrt;
    // Below this |k x c| / |k| a wave normal counts as along the axis (birefringence.cpp's kAlongAxis).
    constexpr double kAlongAxis = 1e-9;
    const T alongAxis2(kAlongAxis * kAlongAxis), sign(side);
    CrystalWavePair<T> w;
    // sDirection: any perpendicular to N at normal incidence.
    const V3<T> sCross = cross(kt, N);
    const T sLength = length(sCross);
    w.s = select(T(1e-12) < sLength, sCross / sLength, perpendicularTo(N));
    // ordinaryField's fallback along the axis: the part of s across it.
    const V3<T> acrossAxis = w.s - c * dot(c, w.s);
    // extraordinaryRoots
    w.epsN = epsilonTimes(nO, nE, c, N), w.epsKt = epsilonTimes(nO, nE, c, kt);
    w.a = dot(N, w.epsN), w.b = dot(kt, w.epsN);
    const T cq = dot(kt, w.epsKt) - nO * nO * nE * nE;
    w.discriminant = w.b * w.b - w.a * cq;
    w.kt2 = dot(kt, kt);
    // ordinaryInterfaceWave
    w.q2 = nO * nO - w.kt2;
    w.qO = sign * sqrt(w.q2);
    w.kO = kt + N * w.qO;
    const V3<T> eO = cross(w.kO, c);
    w.fieldO = select(alongAxis2 * dot(w.kO, w.kO) < dot(eO, eO), eO, acrossAxis);
    // extraordinaryInterfaceWave
    w.root = sqrt(w.discriminant);
    w.qE = (-w.b + sign * w.root) / w.a;
    w.kE = kt + N * w.qE;
    w.rayNormalE = (sign * w.root) / length(w.epsKt + w.epsN * w.qE);
    const V3<T> dE = c * dot(w.kE, w.kE) - w.kE * dot(w.kE, c);
    const T io = T(1.0) / (nO * nO), ie = T(1.0) / (nE * nE);
    // extraordinaryField: E = eps^-1 D, or along the axis k x E_o.
    const V3<T> eOE = cross(w.kE, c);
    const V3<T> fieldOE = select(alongAxis2 * dot(w.kE, w.kE) < dot(eOE, eOE), eOE, acrossAxis);
    w.fieldE = select(alongAxis2 * dot(w.kE, w.kE) * dot(w.kE, w.kE) < dot(dE, dE),
                      dE * io + c * (dot(c, dE) * (ie - io)), cross(w.kE, fieldOE));
    return w;
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
    // forEachNumber's: the incident s field, each wave's flux ratio and two amplitudes, then the transmitted
    // waves' plane waves.
    static constexpr int kFluxes = 3, kTransmitted = kFluxes + 4 * 3, kPerWave = 3 * 3 + 1;
    static constexpr int kNumbers = kTransmitted + 2 * kPerWave;
    Mask met[kConditions];
    V3<T> incidentNormal, incidentS, incidentP;
    T incidentIndex;
    EntryWave<T> reflected[2], transmitted[2];

    // f(x) for each number a photon's choice reads (EntryLane), in a fixed order: the lanes store only these,
    // so the compiler drops what only the others need (the reflected waves' wave normal and fields, the
    // incident wave normal and p field: 12 vector divisions of the entry's).
    template <class F>
    FACETLIGHT_AI void forEachNumber(F&& f) {
        f(incidentS.x), f(incidentS.y), f(incidentS.z);
        for (EntryWave<T>* w : {&reflected[0], &reflected[1], &transmitted[0], &transmitted[1]})
            f(w->fluxRatio), f(w->amplitude[0]), f(w->amplitude[1]);
        for (EntryWave<T>* w : {&transmitted[0], &transmitted[1]}) {
            for (V3<T>* v : {&w->waveNormal, &w->ray, &w->field}) f(v->x), f(v->y), f(v->z);
            f(w->index);
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
    const T zero(0.0), n(nOutside);
    UniaxialEntry<T> e;
    const V3<T> c = lift<T>(axis);
    auto epsilonTimes = [&](const V3<T>& v) FACETLIGHT_AL { return uniaxial::epsilonTimes(nO, nE, c, v); };

    const V3<T> N = -outwardNormal;
    const T cosI = dot(direction, N);
    const V3<T> kt = (direction - N * cosI) * n;
    const CrystalWavePair<T> w = crystalWavePair(nO, nE, c, kt, N, 1.0);
    const V3<T>& s = w.s;
    // isotropicWave: incident (+1) and reflected (-1) s and p
    const T outside2 = n * n - w.kt2;
    const T qI = sqrt(outside2), qR = -qI;
    const V3<T> kI = kt + N * qI, kR = kt + N * qR;
    const T inverseN(1 / nOutside);
    const V3<T> fieldIP = cross(kI, s) * inverseN, fieldRP = cross(kR, s) * inverseN;

    e.met[0] = zero < cosI;
    e.met[1] = zero < w.q2;
    e.met[2] = zero < w.discriminant;
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
    tangential(w.kO, w.fieldO, cO);
    tangential(w.kE, w.fieldE, cE);
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
    fill(e.transmitted[0], w.kO, w.fieldO, x[2], false, false, w.qO / nO);
    fill(e.transmitted[1], w.kE, w.fieldE, x[3], false, true, w.rayNormalE);
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

// One wave of leaveCrystal()'s (a crystal wave reflected, an outside wave transmitted) as OutgoingWave holds
// it for the one incident wave: its plane wave (ray = waveNormal but for the extraordinary wave; unset for an
// evanescent wave), flux ratio, complex amplitude (re, im) and share.
template <class T>
struct LeavingWave {
    V3<T> waveNormal, ray, field;
    T index, fluxRatio, amplitude[2], share;
};

// The waves of leaveCrystal() where both of the crystal's reflected waves propagate: reflected ordinary and
// extraordinary, transmitted s and p (evanescent under total internal reflection). `met` as UniaxialEntry's.
template <class T>
struct UniaxialLeaving {
    using Mask = decltype(T{} < T{});
    static constexpr int kConditions = 7;
    static constexpr int kStartConditions = 6;  // startLeaving()'s; the last, leaveInto...()'s
    // forEachNumber's: the four shares, the reflected waves' plane waves, the transmitted amplitudes, then
    // the s wave's ray and field.
    static constexpr int kReflected = 4, kPerWave = 3 * 3 + 1, kAmplitudes = kReflected + 2 * kPerWave;
    static constexpr int kOut = kAmplitudes + 2 * 2, kNumbers = kOut + 2 * 3;
    Mask met[kConditions];
    LeavingWave<T> reflected[2], transmitted[2];

    // f(x) for each number a photon's choice reads (LeavingLane), in a fixed order, as UniaxialEntry's.
    template <class F>
    FACETLIGHT_AI void forEachNumber(F&& f) {
        for (LeavingWave<T>* w : {&reflected[0], &reflected[1], &transmitted[0], &transmitted[1]})
            f(w->share);
        for (LeavingWave<T>* w : {&reflected[0], &reflected[1]}) {
            for (V3<T>* v : {&w->waveNormal, &w->ray, &w->field}) f(v->x), f(v->y), f(v->z);
            f(w->index);
        }
        for (LeavingWave<T>* w : {&transmitted[0], &transmitted[1]}) f(w->amplitude[0]), f(w->amplitude[1]);
        for (V3<T>* v : {&transmitted[0].ray, &transmitted[0].field}) f(v->x), f(v->y), f(v->z);
    }
};

// What leaveCrystal() works out before the outside waves: the incidence, the crystal's reflected waves (their
// plane waves and flux ratios in `out`, their fields' scale), the columns of the 2x2 system and the incident
// wave's tangential components (birefringence.cpp's matchFields), and n^2 - kt^2, whose sign says whether the
// outside waves propagate.
template <class T>
struct LeavingStart {
    UniaxialLeaving<T> out;
    V3<T> N, kt, s;
    T n, inverseN, cO[4], cE[4], b[4], fieldScale[2], incidentFlux, outside2;
};

// leaveCrystal(UniaxialMedium{nO, nE, axis}, incident, outwardNormal, nOutside) up to the outside waves, for
// the incident plane wave (waveNormal, ray, field, index; ordinary where the mask says, else
// extraordinary).
template <class T, class Mask>
FACETLIGHT_AI LeavingStart<T> startLeaving(T nO, T nE, const Vec3& axis, const V3<T>& waveNormal,
                                           const V3<T>& ray, const V3<T>& field, T index, Mask ordinary,
                                           const V3<T>& outwardNormal, double nOutside) {
    using std::sqrt;
    const T zero(0.0), one(1.0);
    LeavingStart<T> st;
    UniaxialLeaving<T>& e = st.out;
    st.n = T(nOutside), st.inverseN = T(1 / nOutside);
    const V3<T> c = lift<T>(axis);
    const V3<T>& N = st.N = outwardNormal;
    auto epsilonTimes = [&](const V3<T>& v) FACETLIGHT_AL { return uniaxial::epsilonTimes(nO, nE, c, v); };
    // insideIncidence
    const V3<T> k = waveNormal * index;
    const V3<T>& kt = st.kt = k - N * dot(k, N);
    const CrystalWavePair<T> w = crystalWavePair(nO, nE, c, kt, N, -1.0);
    const V3<T>& s = st.s = w.s;
    const T rayNormalO = w.qO / nO;
    // leaveWith: the incident wave's ray normal component from its reflected twin's root
    const T twin = select(ordinary, -rayNormalO, w.root / length(w.epsKt + w.epsN * ((-w.b + w.root) / w.a)));
    const T rayNormal = select(zero < twin, twin, dot(ray, N));

    e.met[0] = zero < dot(ray, N);
    e.met[1] = zero < w.q2;
    e.met[2] = zero < w.discriminant;
    e.met[3] = zero < nO;
    e.met[4] = zero < nE;
    st.outside2 = st.n * st.n - w.kt2;
    e.met[5] = zero < st.outside2 * st.outside2;  // the outside waves propagate or are evanescent

    // matchFields: the crystal's waves reflected (columns negated), the isotropic ones transmitted.
    const V3<T> t2 = cross(N, s);
    auto tangential = [&](const V3<T>& kw, const V3<T>& fw, T out[4]) FACETLIGHT_AL {
        const V3<T> h = cross(kw, fw);
        out[0] = dot(fw, s), out[1] = dot(fw, t2), out[2] = dot(h, s), out[3] = dot(h, t2);
    };
    tangential(w.kO, w.fieldO, st.cO);
    tangential(w.kE, w.fieldE, st.cE);
    for (int i = 0; i < 4; ++i) st.cO[i] = -st.cO[i], st.cE[i] = -st.cE[i];
    tangential(k, field, st.b);
    const T across = select(ordinary, one, length(waveNormal - field * dot(waveNormal, field)));
    st.incidentFlux = index * across * rayNormal;
    auto plane = [&](LeavingWave<T>& w, const V3<T>& kw, const V3<T>& fw, bool extraordinary, T rayNormalW,
                     T& fieldScale) FACETLIGHT_AL {
        fieldScale = length(fw);
        w.field = fw / fieldScale;
        w.index = length(kw);
        w.waveNormal = kw / w.index;
        w.ray = w.waveNormal;
        T acrossW = one;
        if (extraordinary) {
            const V3<T> r = epsilonTimes(kw);
            w.ray = r / length(r);
            acrossW = length(w.waveNormal - w.field * dot(w.waveNormal, w.field));
        }
        w.fluxRatio = -(w.index * acrossW * rayNormalW) / st.incidentFlux;
    };
    plane(e.reflected[0], w.kO, w.fieldO, false, rayNormalO, st.fieldScale[0]);
    plane(e.reflected[1], w.kE, w.fieldE, true, w.rayNormalE, st.fieldScale[1]);
    return st;
}

// The rest of leaveCrystal() where the outside waves propagate (n^2 > kt^2).
template <class T>
FACETLIGHT_AI UniaxialLeaving<T> leaveIntoPropagating(const LeavingStart<T>& st) {
    using std::sqrt;
    const T zero(0.0), n = st.n;
    const T* cO = st.cO;
    const T* cE = st.cE;
    const T* b = st.b;
    UniaxialLeaving<T> e = st.out;
    // isotropicWave, side +1
    const T qT = sqrt(st.outside2);
    const V3<T> kT = st.kt + st.N * qT;
    const V3<T> fieldP = cross(kT, st.s) * st.inverseN;
    const T q = qT, g = q / (n * n);
    const T m00 = cO[3] - q * cO[0], m01 = cE[3] - q * cE[0];
    const T m10 = cO[1] + g * cO[2], m11 = cE[1] + g * cE[2];
    const T det = m00 * m11 - m01 * m10;
    e.met[6] = zero < det * det;
    const T r0 = b[3] - q * b[0], r1 = b[1] + g * b[2];
    const T u0 = (r0 * m11 - m01 * r1) / det, u1 = (m00 * r1 - m10 * r0) / det;
    const T x[4] = {u0, u1, b[0] - cO[0] * u0 - cE[0] * u1, (cO[2] * u0 + cE[2] * u1 - b[2]) / n};
    for (int j = 0; j < 2; ++j) {
        LeavingWave<T>& w = e.reflected[j];
        w.amplitude[0] = x[j] * st.fieldScale[j], w.amplitude[1] = zero;
        w.share = w.fluxRatio * (w.amplitude[0] * w.amplitude[0] + zero * zero);
    }
    const V3<T> fields[2] = {st.s, fieldP};
    for (int j = 0; j < 2; ++j) {
        LeavingWave<T>& w = e.transmitted[j];
        const T fieldScale = length(fields[j]);
        w.field = fields[j] / fieldScale;
        w.index = length(kT);
        w.waveNormal = kT / w.index;
        w.ray = w.waveNormal;
        w.fluxRatio = w.index * (qT / n) / st.incidentFlux;
        w.amplitude[0] = x[2 + j] * fieldScale, w.amplitude[1] = zero;
        w.share = w.fluxRatio * (w.amplitude[0] * w.amplitude[0] + zero * zero);
    }
    return e;
}

// The rest of leaveCrystal() under total internal reflection (n^2 < kt^2): the outside waves' q = i r, and
// the 2x2 system in complex numbers (re, im), each operation std::complex's under -fcx-limited-range (the
// textbook product; a quotient by a real number part by part; birefringence.cpp's divide() z conj(w) /
// |w|^2), less the products with a part known to be zero, which change no bits of the parts that are not.
template <class T>
FACETLIGHT_AI UniaxialLeaving<T> leaveIntoEvanescent(const LeavingStart<T>& st) {
    using std::sqrt;
    struct C {
        T re, im;
    };
    auto mul = [](C a, C b) FACETLIGHT_AL { return C{a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; };
    auto sub = [](C a, C b) FACETLIGHT_AL { return C{a.re - b.re, a.im - b.im}; };
    const T zero(0.0), n = st.n;
    const T* cO = st.cO;
    const T* cE = st.cE;
    const T* b = st.b;
    UniaxialLeaving<T> e = st.out;
    const T r = sqrt(-st.outside2), gi = r / (n * n);  // q = (0, r), g = q / n^2
    // c - q a and c + g a for real a, c
    auto minusQ = [&](T cc, T a) FACETLIGHT_AL { return C{cc, -(r * a)}; };
    auto plusG = [&](T cc, T a) FACETLIGHT_AL { return C{cc, gi * a}; };
    const C m00 = minusQ(cO[3], cO[0]), m01 = minusQ(cE[3], cE[0]);
    const C m10 = plusG(cO[1], cO[2]), m11 = plusG(cE[1], cE[2]);
    const C det = sub(mul(m00, m11), mul(m01, m10));
    const T norm = det.re * det.re + det.im * det.im;
    e.met[6] = zero < norm;
    const C r0 = minusQ(b[3], b[0]), r1 = plusG(b[1], b[2]);
    const C conj{det.re, -det.im};
    auto divide = [&](C z) FACETLIGHT_AL {
        const C w = mul(z, conj);
        return C{w.re / norm, w.im / norm};
    };
    const C u0 = divide(sub(mul(r0, m11), mul(m01, r1))), u1 = divide(sub(mul(m00, r1), mul(m10, r0)));
    const C x[4] = {u0,
                    u1,
                    {b[0] - cO[0] * u0.re - cE[0] * u1.re, -(cO[0] * u0.im) - cE[0] * u1.im},
                    {(cO[2] * u0.re + cE[2] * u1.re - b[2]) / n, (cO[2] * u0.im + cE[2] * u1.im) / n}};
    for (int j = 0; j < 2; ++j) {
        LeavingWave<T>& w = e.reflected[j];
        w.amplitude[0] = x[j].re * st.fieldScale[j], w.amplitude[1] = x[j].im * st.fieldScale[j];
        w.share = w.fluxRatio * (w.amplitude[0] * w.amplitude[0] + w.amplitude[1] * w.amplitude[1]);
    }
    // The evanescent waves' fields: s, and p = k x s / n with k = (kt, r N); each scaled by its Hermitian
    // norm.
    const V3<T> pRe = cross(st.kt, st.s) * st.inverseN, pIm = cross(st.N * r, st.s) * st.inverseN;
    const T scales[2] = {sqrt(dot(st.s, st.s)),
                         sqrt((pRe.x * pRe.x + pIm.x * pIm.x) + (pRe.y * pRe.y + pIm.y * pIm.y) +
                              (pRe.z * pRe.z + pIm.z * pIm.z))};
    for (int j = 0; j < 2; ++j) {
        LeavingWave<T>& w = e.transmitted[j];
        w.fluxRatio = zero;
        w.amplitude[0] = x[2 + j].re * scales[j], w.amplitude[1] = x[2 + j].im * scales[j];
        w.share = zero * (w.amplitude[0] * w.amplitude[0] + w.amplitude[1] * w.amplitude[1]);
    }
    return e;
}

// leaveCrystal's InterfaceWaves, into `out`, of a scalar leaving whose conditions are all met, `incident` the
// crystal wave given.
inline void putInterfaceWaves(const UniaxialLeaving<double>& e, const PlaneWave& incident, bool evanescent,
                              InterfaceWaves& out) {
    auto vec = [](const V3<double>& v) { return Vec3{v.x, v.y, v.z}; };
    auto put = [&](OutgoingWave& o, WaveMode mode, const LeavingWave<double>& w, bool propagating) {
        o.wave =
            propagating ? PlaneWave{mode, vec(w.waveNormal), vec(w.ray), vec(w.field), w.index} : PlaneWave{};
        o.propagating = propagating;
        o.fluxRatio = w.fluxRatio;
        o.amplitude[0] = Complex(w.amplitude[0], w.amplitude[1]), o.amplitude[1] = {};
        o.share[0] = w.share, o.share[1] = 0;
    };
    out.incidentCount = 1;
    out.incident[0] = incident;
    out.incident[1] = PlaneWave{};
    put(out.reflected[0], WaveMode::Ordinary, e.reflected[0], true);
    put(out.reflected[1], WaveMode::Extraordinary, e.reflected[1], true);
    put(out.transmitted[0], WaveMode::S, e.transmitted[0], !evanescent);
    put(out.transmitted[1], WaveMode::P, e.transmitted[1], !evanescent);
}

// The draw among an interface's waves, written once over the number type and for entries and leavings
// alike: u is the photon's next Rng::uniform(), then the shares of a pair of waves the photon takes together
// (an entry's reflected s and p waves, a leaving's transmitted s and p waves) and of the two crystal waves
// (ordinary, then extraordinary: transmitted on entry, reflected on leaving). The photon takes the pair where
// `pair`, else the ordinary wave where `ordinary`, else the extraordinary one
// (PhotonWalker::chooseCrystalWave(), chooseLeavingWave()).
template <class T>
struct WaveDraw {
    decltype(T{} < T{}) pair, ordinary;
};
template <class T>
FACETLIGHT_AI WaveDraw<T> drawWave(T u, T pairS, T pairP, T ordinary, T extraordinary) {
    const T pair = pairS + pairP;
    const T x = u * (pair + ordinary + extraordinary);
    return {x < pair, x < pair + ordinary};
}

// One lane's entry among several kept by number (UniaxialEntry<double>::forEachNumber's order, number i at
// numbers[i * stride]): what a photon's choice reads of it (PhotonWalker::chooseCrystalWave()), the values
// putInterfaceWaves() would put into InterfaceWaves.
struct EntryLane {
    using Entry = UniaxialEntry<double>;
    static constexpr int kNotDrawn = 2;
    const double* numbers;
    size_t stride;
    // Where the lanes drew for it (drawEntryLanes()): -1 reflected, 0 or 1 the ordinary or extraordinary
    // wave.
    int drawn = kNotDrawn;

    double number(int i) const { return numbers[size_t(i) * stride]; }
    Vec3 vec(int i) const { return {number(i), number(i + 1), number(i + 2)}; }
    Vec3 incidentS() const { return vec(0); }
    // Wave w: reflected s and p, then transmitted ordinary and extraordinary.
    double fluxRatio(int w) const { return number(Entry::kFluxes + 3 * w); }
    Complex amplitude(int w, int i) const { return Complex(number(Entry::kFluxes + 3 * w + 1 + i), 0.0); }
    PlaneWave transmittedWave(int j) const {
        const int at = Entry::kTransmitted + Entry::kPerWave * j;
        return {j ? WaveMode::Extraordinary : WaveMode::Ordinary, vec(at), vec(at + 3), vec(at + 6),
                number(at + 9)};
    }
    Vec3 ordinaryNormal() const { return vec(Entry::kTransmitted); }
};

// One lane's leaving among several kept by number (UniaxialLeaving<double>::forEachNumber's order, number i
// at numbers[i * stride]): what a photon's choice reads of it (PhotonWalker::chooseLeavingWave()), the values
// putInterfaceWaves() would put into InterfaceWaves; and, where the lanes drew for it (drawLeavingLanes()),
// the wave drawn: -1 out through the s and p waves, 0 or 1 the reflected ordinary or extraordinary wave.
struct LeavingLane {
    using Leaving = UniaxialLeaving<double>;
    static constexpr int kNotDrawn = 2;
    const double* numbers;
    size_t stride;
    bool evanescent;
    int drawn = kNotDrawn;

    double number(int i) const { return numbers[size_t(i) * stride]; }
    Vec3 vec(int i) const { return {number(i), number(i + 1), number(i + 2)}; }
    double reflectedShare(int j) const { return number(j); }
    double transmittedShare(int j) const { return number(2 + j); }
    PlaneWave reflectedWave(int j) const {
        const int at = Leaving::kReflected + Leaving::kPerWave * j;
        return {j ? WaveMode::Extraordinary : WaveMode::Ordinary, vec(at), vec(at + 3), vec(at + 6),
                number(at + 9)};
    }
    Complex transmittedAmplitude(int j) const {
        return Complex(number(Leaving::kAmplitudes + 2 * j), number(Leaving::kAmplitudes + 2 * j + 1));
    }
    // The s wave's ray and field (unset when evanescent).
    Vec3 transmittedRay() const { return evanescent ? Vec3{} : vec(Leaving::kOut); }
    Vec3 transmittedField() const { return evanescent ? Vec3{} : vec(Leaving::kOut + 3); }
};

#undef FACETLIGHT_AI
#undef FACETLIGHT_AL

}  // namespace uniaxial
}  // namespace facetlight
