#include "optics/birefringence.h"

#include <algorithm>
#include <cmath>
#include <type_traits>

#include "optics/uniaxial_interface.h"
#include "util/error.h"

namespace facetlight {
namespace {

// A complex 3-vector. Products are bilinear (no conjugation) as in Maxwell's equations for complex k; the
// Hermitian norm only scales evanescent fields, whose scale carries no energy.
struct CVec3 {
    Complex x, y, z;
};

CVec3 operator+(const CVec3& a, const CVec3& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
CVec3 operator-(const CVec3& a, const CVec3& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
CVec3 operator*(const CVec3& a, Complex s) {
    return {a.x * s, a.y * s, a.z * s};
}
Complex dot(const CVec3& a, const CVec3& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
CVec3 cross(const CVec3& a, const CVec3& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double norm2(const CVec3& a) {
    return std::norm(a.x) + std::norm(a.y) + std::norm(a.z);
}
Vec3 realPart(const CVec3& a) {
    return {a.x.real(), a.y.real(), a.z.real()};
}
double norm2(const Vec3& a) {
    return dot(a, a);
}
const Vec3& realPart(const Vec3& a) {
    return a;
}

// The interface arithmetic is written once over its number types: double for a pair of waves (the crystal's
// two, or the s and p waves outside) that both propagate, their wave vectors and fields being real (light
// entering from air; inside, every wave but the outside ones under total internal reflection), Complex for a
// pair with an evanescent wave. Real numbers in complex arithmetic round the same, so the types agree but for
// the 2x2 division's rounding.
template <class T>
using Vec3Of = std::conditional_t<std::is_same_v<T, double>, Vec3, CVec3>;
template <class T>
Vec3Of<T> lift(const Vec3& v) {
    return {v.x, v.y, v.z};
}

// Any unit vector perpendicular to unit n (Duff et al., "Building an orthonormal basis, revisited", 2017).
Vec3 perpendicularTo(const Vec3& n) {
    const uniaxial::V3<double> p = uniaxial::perpendicularTo(uniaxial::V3<double>{n.x, n.y, n.z});
    return {p.x, p.y, p.z};
}

// Below this |k x c| / |k| the wave normal counts as along the axis, where the ordinary and extraordinary
// waves are degenerate and k x c no longer fixes a direction.
constexpr double kAlongAxis = 1e-9;

// eps^-1 v for eps = n_o^2 I + (n_e^2 - n_o^2) c c^T.
template <class V>
V inverseEpsilonTimes(const UniaxialMedium& m, const V& v) {
    const double io = 1 / (m.nO * m.nO), ie = 1 / (m.nE * m.nE);
    const V c{m.axis.x, m.axis.y, m.axis.z};
    return v * io + c * (dot(c, v) * (ie - io));
}
Vec3 epsilonTimes(const UniaxialMedium& m, const Vec3& v) {
    return v * (m.nO * m.nO) + m.axis * (dot(m.axis, v) * (m.nE * m.nE - m.nO * m.nO));
}

// E of the ordinary wave of (possibly complex) wave vector k: along k x c, perpendicular to the axis and to k
// (Born & Wolf ch. 15). Along the axis, the part of `reference` perpendicular to the axis.
template <class V>
V ordinaryField(const UniaxialMedium& m, const V& k, const Vec3& reference) {
    const V e = cross(k, V{m.axis.x, m.axis.y, m.axis.z});
    if (norm2(e) > kAlongAxis * kAlongAxis * norm2(k)) return e;
    const Vec3 r = reference - m.axis * dot(m.axis, reference);
    return {r.x, r.y, r.z};
}

// E of the extraordinary wave: D lies in the plane of k and c, perpendicular to k, D ~ c (k.k) - k (k.c), and
// E = eps^-1 D (Yariv & Yeh ch. 4). Along the axis, k x E_o.
template <class V>
V extraordinaryField(const UniaxialMedium& m, const V& k, const Vec3& reference) {
    const V c{m.axis.x, m.axis.y, m.axis.z};
    const V d = c * dot(k, k) - k * dot(k, c);
    if (norm2(d) > kAlongAxis * kAlongAxis * norm2(k) * norm2(k)) return inverseEpsilonTimes(m, d);
    return cross(k, ordinaryField(m, k, reference));
}

// One wave of the interface problem: its wave vector and field (complex when evanescent), and for a
// propagating wave the normal component of its unit ray direction. That component is taken from the root
// (q / n, or sqrt(b^2 - a c) / |eps k|) rather than from the vectors: near grazing it is small, and the
// incident and the reflected wave of the same kind then carry exactly opposite fluxes, which keeps energy
// conserved to rounding there too.
template <class T>
struct Wave {
    WaveMode mode;
    Vec3Of<T> k;
    Vec3Of<T> field;
    bool propagating;
    double rayNormal;
    T q;  // N . k
};

// The principal square root of a real x, as std::sqrt(Complex(x, +0)) gives it, without the complex call (x
// is not negative where T is double).
template <class T>
T principalRoot(double x) {
    if constexpr (std::is_same_v<T, double>) {
        return std::sqrt(x);
    } else {
        return x >= 0 ? Complex(std::sqrt(x), 0) : Complex(0, std::sqrt(-x));
    }
}

// The normal component q of the wave vector kt + q N of each outgoing wave. `side` is +1 for the waves whose
// energy leaves along +N (transmitted), -1 for those leaving along -N (reflected); an evanescent wave must
// decay on its side, Im(q) side > 0. For |k|^2 = n^2: q = side sqrt(n^2 - kt^2), the flux is along k. For the
// extraordinary wave, k.eps.k = n_o^2 n_e^2 is the quadratic a q^2 + 2 b q + c = 0 with a = N.eps.N,
// b = kt.eps.N, c = kt.eps.kt - n_o^2 n_e^2; its ray is along eps k (the normal to the index surface), whose
// normal component is b + a q = +-sqrt(b^2 - a c): the root with +sqrt sends energy along +N whichever way
// its wave normal points. The principal complex square root gives the decaying root for either side.
template <class T>
Wave<T> isotropicWave(WaveMode mode, double n, const Vec3& kt, const Vec3& N, const Vec3& s, int side) {
    const T q = double(side) * principalRoot<T>(n * n - dot(kt, kt));
    const Vec3Of<T> k = lift<T>(kt) + lift<T>(N) * q;
    const bool propagating = n * n - dot(kt, kt) > 0;
    const Vec3Of<T> field = mode == WaveMode::S ? lift<T>(s) : cross(k, lift<T>(s)) * (1 / n);
    return {mode, k, field, propagating, propagating ? std::real(q) / n : 0, q};
}

template <class T>
Wave<T> ordinaryInterfaceWave(const UniaxialMedium& m, const Vec3& kt, const Vec3& N, const Vec3& s,
                              int side) {
    const double q2 = m.nO * m.nO - dot(kt, kt);
    const T q = double(side) * principalRoot<T>(q2);
    const Vec3Of<T> k = lift<T>(kt) + lift<T>(N) * q;
    return {WaveMode::Ordinary, k, ordinaryField(m, k, s), q2 > 0, q2 > 0 ? std::real(q) / m.nO : 0, q};
}

// The extraordinary wave's quadratic for a tangential kt (above): eps N and eps kt, whose sum eps kt + q eps
// N is eps k, a, b and the discriminant b^2 - a c, shared by the waves of both sides.
struct ExtraordinaryRoots {
    Vec3 epsN, epsKt;
    double a, b, discriminant;
};
ExtraordinaryRoots extraordinaryRoots(const UniaxialMedium& m, const Vec3& kt, const Vec3& N) {
    const Vec3 epsN = epsilonTimes(m, N), epsKt = epsilonTimes(m, kt);
    const double a = dot(N, epsN), b = dot(kt, epsN);
    const double c = dot(kt, epsKt) - m.nO * m.nO * m.nE * m.nE;
    return {epsN, epsKt, a, b, b * b - a * c};
}
// The root q of `side` and, when it propagates, the normal component of its unit ray, sqrt(b^2 - a c) / |eps
// k|.
template <class T>
T extraordinaryRoot(const ExtraordinaryRoots& r, int side) {
    return (-r.b + double(side) * principalRoot<T>(r.discriminant)) / r.a;
}
double extraordinaryRayNormal(const ExtraordinaryRoots& r, int side, double q) {
    return side * std::sqrt(r.discriminant) / length(r.epsKt + r.epsN * q);
}

template <class T>
Wave<T> extraordinaryInterfaceWave(const UniaxialMedium& m, const ExtraordinaryRoots& r, const Vec3& kt,
                                   const Vec3& N, const Vec3& s, int side) {
    const T q = extraordinaryRoot<T>(r, side);
    const Vec3Of<T> k = lift<T>(kt) + lift<T>(N) * q;
    const bool propagating = r.discriminant > 0;
    const double rayNormal = propagating ? extraordinaryRayNormal(r, side, std::real(q)) : 0;
    return {WaveMode::Extraordinary, k, extraordinaryField(m, k, s), propagating, rayNormal, q};
}

// The time-averaged Poynting flux along N of propagating wave p whose ray has the normal component rayNormal,
// up to the factor common to every wave: N . Re(E x conj(H)) with H = k x E, i.e. |k - E (k.E)| times
// rayNormal, where |k - E (k.E)| = |k| unless p is extraordinary (E is across k in the others).
double normalFlux(const PlaneWave& p, double rayNormal) {
    const bool acrossK = p.mode == WaveMode::S || p.mode == WaveMode::P || p.mode == WaveMode::Ordinary;
    const double across = acrossK ? 1 : length(p.waveNormal - p.field * dot(p.waveNormal, p.field));
    return p.index * across * rayNormal;
}

// The ray (energy) direction of propagating wave p of wave vector k: along eps k for an extraordinary wave
// (the normal to the index surface), along k - E (E.k) for a biaxial crystal's (the Poynting vector
// E x (k x E) of a unit real E), else along k.
Vec3 rayOf(const UniaxialMedium* crystal, const PlaneWave& p, const Vec3& k) {
    return p.mode == WaveMode::Extraordinary ? normalize(epsilonTimes(*crystal, k)) : p.waveNormal;
}
Vec3 rayOf(const BiaxialMedium*, const PlaneWave& p, const Vec3& k) {
    const bool crystal = p.mode == WaveMode::Fast || p.mode == WaveMode::Slow;
    return crystal ? normalize(k - p.field * dot(p.field, k)) : p.waveNormal;
}

// The propagating wave w as a PlaneWave, its unit field e given.
template <class M, class T>
PlaneWave toPlaneWave(const M* crystal, const Wave<T>& w, const Vec3& e) {
    const Vec3 k = realPart(w.k);
    PlaneWave p;
    p.mode = w.mode;
    p.index = length(k);
    p.waveNormal = k / p.index;
    p.field = e;
    p.ray = rayOf(crystal, p, k);
    return p;
}
template <class M, class T>
PlaneWave toPlaneWave(const M* crystal, const Wave<T>& w) {
    return toPlaneWave(crystal, w, normalize(realPart(w.field)));
}

// The four tangential components (E.t1, E.t2, H.t1, H.t2) of a wave, t1 = s, t2 = N x s.
template <class T>
void tangential(const Wave<T>& w, const Vec3& t1, const Vec3& t2, T out[4]) {
    const Vec3Of<T> h = cross(w.k, w.field);
    const Vec3Of<T> a = lift<T>(t1), b = lift<T>(t2);
    out[0] = dot(w.field, a);
    out[1] = dot(w.field, b);
    out[2] = dot(h, a);
    out[3] = dot(h, b);
}

// z / w, complex without the library's scaled division (__divdc3): |w| is far from overflow here.
template <class T>
T divide(T z, T w) {
    if constexpr (std::is_same_v<T, double>) {
        return z / w;
    } else {
        return z * std::conj(w) / std::norm(w);
    }
}

// A propagating wave whose PlaneWave and normalFlux are known before matchFields, which then need not work
// them out again: a biaxial crystal's as biaxialWaves found it (unit field, wave normal and ray from the
// eigenproblem; flux |k - E (E.k)| times its ray's normal component), and an s or p wave outside.
struct KnownWave {
    PlaneWave wave;
    double flux;
};

// The s or p wave w outside (isotropicWave, index n), where it propagates: its field is unit as made (s, and
// k x s / n with k across s and |k| = n).
template <class I>
KnownWave isotropicKnown(const Wave<I>& w, double n) {
    KnownWave o{};
    o.wave.mode = w.mode;
    o.wave.index = n;
    o.wave.waveNormal = realPart(w.k) * (1 / n);
    o.wave.ray = o.wave.waveNormal;
    o.wave.field = realPart(w.field);
    o.flux = n * w.rayNormal;
    return o;
}

// Matches tangential E and H across the interface for `count` incident waves: incident + reflected =
// transmitted, the unknowns being the two reflected and the two transmitted amplitudes (n the isotropic
// medium's index). Fills the outgoing waves' amplitudes, flux ratios and shares.
//
// The isotropic medium's s and p waves need no general 4x4 solve: with q = N.k their tangential components
// are s: (1, 0, 0, q) and p: (0, q / n, -n, 0) (E = k x s / n, H = k x E = -n s as k.k = n^2), so s appears
// only in rows 0 and 3 and p only in rows 1 and 2. Eliminating them leaves a 2x2 system for the crystal's
// two waves (Yariv & Yeh ch. 4; Lekner 1991 reduces it the same way), solved by Cramer's rule. The crystal's
// waves are reflected or transmitted as crystalReflects says, the isotropic waves iso[] (s, p) the others;
// where known is given, the propagating ones among them are known[0], [1] (the crystal's) and known[2], [3]
// (iso[]), and the incident flux is incidentFlux.
template <class C, class I, class In, class M>
void matchFields(const M& crystal, bool crystalReflects, const Wave<In> incident[2], int count,
                 const Wave<C> crystalWaves[2], const Wave<I> iso[2], const Vec3& N, const Vec3& s, double n,
                 InterfaceWaves& out, const KnownWave* known, double knownIncidentFlux) {
    using T = std::conditional_t<std::is_same_v<C, double> && std::is_same_v<I, double>, double, Complex>;
    const Vec3 t2 = cross(N, s);
    // incident = sum of u_j A_j: A_j = +transmitted_j, -reflected_j.
    const double crystalSign = crystalReflects ? -1 : 1, isoSign = -crystalSign;
    C c[2][4];  // the crystal waves' columns A
    for (int j = 0; j < 2; ++j) {
        tangential(crystalWaves[j], s, t2, c[j]);
        for (C& v : c[j]) v *= crystalSign;
    }
    const I q = iso[0].q, g = q / (n * n);
    const T m00 = c[0][3] - q * c[0][0], m01 = c[1][3] - q * c[1][0];
    const T m10 = c[0][1] + g * c[0][2], m11 = c[1][1] + g * c[1][2];
    const T det = m00 * m11 - m01 * m10;
    if (!(std::norm(det) > 0)) throw Error("birefringence: the interface equations are singular");

    // x[row][i]: the amplitude of wave `row` (reflected 0, 1, transmitted 0, 1) for incident wave i.
    Complex x[4][2];
    const int crystalRow = crystalReflects ? 0 : 2, isoRow = 2 - crystalRow;
    for (int i = 0; i < count; ++i) {
        In b[4];
        tangential(incident[i], s, t2, b);
        const T r0 = b[3] - q * b[0], r1 = b[1] + g * b[2];
        const T u0 = divide(r0 * m11 - m01 * r1, det), u1 = divide(m00 * r1 - m10 * r0, det);
        x[crystalRow][i] = u0;
        x[crystalRow + 1][i] = u1;
        x[isoRow][i] = isoSign * (b[0] - c[0][0] * u0 - c[1][0] * u1);
        x[isoRow + 1][i] = isoSign * (c[0][2] * u0 + c[1][2] * u1 - b[2]) / n;
    }

    // Every incident basis wave has a unit real field and the same wave vector, so one incident flux serves
    // (out.incident[0] is set).
    const double incidentFlux = known ? knownIncidentFlux : normalFlux(out.incident[0], incident[0].rayNormal);
    auto fill = [&](OutgoingWave& o, const auto& w, const M* medium, int row, double sign,
                    const KnownWave* plane) {
        o.propagating = w.propagating;
        double fieldScale;
        if (w.propagating && plane) {
            fieldScale = 1;
            o.wave = plane->wave;
            o.fluxRatio = sign * plane->flux / incidentFlux;
        } else if (w.propagating) {
            const Vec3 field = realPart(w.field);
            fieldScale = length(field);
            o.wave = toPlaneWave(medium, w, field / fieldScale);
            o.fluxRatio = sign * normalFlux(o.wave, w.rayNormal) / incidentFlux;
        } else {
            fieldScale = std::sqrt(norm2(w.field));
        }
        for (int i = 0; i < count; ++i) {
            // The amplitude refers to the unit field (wave.field), not to the unnormalised one solved for.
            o.amplitude[i] = x[row][i] * fieldScale;
            o.share[i] = o.fluxRatio * std::norm(o.amplitude[i]);
        }
    };
    for (int j = 0; j < 2; ++j) {
        fill(crystalReflects ? out.reflected[j] : out.transmitted[j], crystalWaves[j], &crystal,
             crystalRow + j, crystalSign, known ? known + j : nullptr);
        fill(crystalReflects ? out.transmitted[j] : out.reflected[j], iso[j], nullptr, isoRow + j, isoSign,
             known ? known + 2 + j : nullptr);
    }
}

// s: perpendicular to the plane of incidence, normalize(kt x N); any perpendicular to N at normal incidence.
Vec3 sDirection(const Vec3& kt, const Vec3& N) {
    const Vec3 s = cross(kt, N);
    const double len = length(s);
    return len > 1e-12 ? s / len : perpendicularTo(N);
}

// A crystal wave meeting a facet of outward normal N from inside: its wave vector, that vector's part along the
// facet and s. Refuses a wave whose energy does not travel into the facet.
struct InsideIncidence {
    Vec3 k, kt, s;
};
InsideIncidence insideIncidence(const PlaneWave& incident, const Vec3& N) {
    if (!(dot(incident.ray, N) > 0))
        throw Error("birefringence: the wave's energy does not travel into the facet");
    const Vec3 k = incident.waveNormal * incident.index;
    const Vec3 kt = k - N * dot(k, N);
    return {k, kt, sDirection(kt, N)};
}

void checkMedia(const UniaxialMedium& crystal, double nOutside) {
    if (!(crystal.nO > 0 && crystal.nE > 0 && nOutside > 0))
        throw Error("birefringence: indices must be positive");
    if (!uniaxial::mediumChecks(crystal.axis, nOutside))
        throw Error("birefringence: the optic axis must be a unit vector");
}

}  // namespace

double extraordinaryIndex(const UniaxialMedium& medium, const Vec3& waveNormal) {
    const double c = dot(medium.axis, waveNormal);
    const double s2 = std::fmax(0.0, 1 - c * c);
    return 1 / std::sqrt(c * c / (medium.nO * medium.nO) + s2 / (medium.nE * medium.nE));
}

PlaneWave ordinaryWave(const UniaxialMedium& medium, const Vec3& waveNormal) {
    const Wave<double> w{WaveMode::Ordinary,
                         waveNormal * medium.nO,
                         ordinaryField(medium, waveNormal, perpendicularTo(medium.axis)),
                         true,
                         0,
                         0};
    return toPlaneWave(&medium, w);
}

PlaneWave extraordinaryWave(const UniaxialMedium& medium, const Vec3& waveNormal) {
    const Vec3 k = waveNormal * extraordinaryIndex(medium, waveNormal);
    const Wave<double> w{
        WaveMode::Extraordinary, k, extraordinaryField(medium, k, perpendicularTo(medium.axis)), true, 0, 0};
    return toPlaneWave(&medium, w);
}

namespace {

// Light from outside, once the crystal's two waves are known (either medium): the s and p waves incident and
// reflected outside, and the fields matched.
template <class I, class C, class M>
InterfaceWaves fromOutside(const M& crystal, const Wave<C> transmitted[2], const Vec3& kt, const Vec3& N,
                           const Vec3& s, double nOutside, const KnownWave* known = nullptr) {
    const Wave<I> incident[2] = {isotropicWave<I>(WaveMode::S, nOutside, kt, N, s, 1),
                                 isotropicWave<I>(WaveMode::P, nOutside, kt, N, s, 1)};
    const Wave<I> reflected[2] = {isotropicWave<I>(WaveMode::S, nOutside, kt, N, s, -1),
                                  isotropicWave<I>(WaveMode::P, nOutside, kt, N, s, -1)};
    InterfaceWaves out;
    out.incidentCount = 2;
    if (!known) {
        for (int i = 0; i < 2; ++i) out.incident[i] = toPlaneWave<M>(nullptr, incident[i]);
        matchFields(crystal, false, incident, 2, transmitted, reflected, N, s, nOutside, out, nullptr, 0);
        return out;
    }
    // Outside waves known as well (a biaxial crystal's interface).
    const KnownWave all[4] = {known[0], known[1], isotropicKnown(reflected[0], nOutside),
                              isotropicKnown(reflected[1], nOutside)};
    double incidentFlux = 0;
    for (int i = 0; i < 2; ++i) {
        const KnownWave in = isotropicKnown(incident[i], nOutside);
        out.incident[i] = in.wave;
        incidentFlux = in.flux;
    }
    matchFields(crystal, false, incident, 2, transmitted, reflected, N, s, nOutside, out, all, incidentFlux);
    return out;
}

// A crystal wave from inside (`in`, as given in `incident`), once the crystal's reflected waves are known:
// the s and p waves transmitted outside, and the fields matched.
template <class I, class C, class M>
InterfaceWaves fromInside(const M& crystal, const PlaneWave& incident, const Wave<double> in[1],
                          const Wave<C> reflected[2], const Vec3& kt, const Vec3& N, const Vec3& s,
                          double nOutside, const KnownWave* known = nullptr) {
    const Wave<I> transmitted[2] = {isotropicWave<I>(WaveMode::S, nOutside, kt, N, s, 1),
                                    isotropicWave<I>(WaveMode::P, nOutside, kt, N, s, 1)};
    InterfaceWaves out;
    out.incidentCount = 1;
    out.incident[0] = incident;
    if (!known) {
        matchFields(crystal, true, in, 1, reflected, transmitted, N, s, nOutside, out, nullptr, 0);
        return out;
    }
    // Outside waves known as well (a biaxial crystal's interface); the incident wave's flux as normalFlux.
    const KnownWave all[4] = {known[0], known[1], isotropicKnown(transmitted[0], nOutside),
                              isotropicKnown(transmitted[1], nOutside)};
    matchFields(crystal, true, in, 1, reflected, transmitted, N, s, nOutside, out, all,
                normalFlux(incident, in[0].rayNormal));
    return out;
}

// enterCrystal() once its number types are known (C for the crystal's waves, I for those outside): N is
// along the incident energy flow, into the crystal.
template <class C, class I>
InterfaceWaves enterWith(const UniaxialMedium& crystal, const ExtraordinaryRoots& roots, const Vec3& kt,
                         const Vec3& N, const Vec3& s, double nOutside) {
    const Wave<C> transmitted[2] = {ordinaryInterfaceWave<C>(crystal, kt, N, s, 1),
                                    extraordinaryInterfaceWave<C>(crystal, roots, kt, N, s, 1)};
    return fromOutside<I>(crystal, transmitted, kt, N, s, nOutside);
}

// leaveCrystal() once its number types are known: N is along the incident energy flow, out of the crystal; k
// the incident wave vector.
template <class C, class I>
InterfaceWaves leaveWith(const UniaxialMedium& crystal, const PlaneWave& incident,
                         const ExtraordinaryRoots& roots, const Vec3& k, const Vec3& kt, const Vec3& N,
                         const Vec3& s, double nOutside) {
    // The incident wave as given (its field may be any one of a degenerate pair), its ray's normal
    // component from the same root as its reflected twin's (Wave), unless rounding at grazing loses the root;
    // an ordinary twin's is the reflected ordinary wave's negated.
    const Wave<C> reflected[2] = {ordinaryInterfaceWave<C>(crystal, kt, N, s, -1),
                                  extraordinaryInterfaceWave<C>(crystal, roots, kt, N, s, -1)};
    const double twinRayNormal =
        incident.mode == WaveMode::Ordinary ? -reflected[0].rayNormal
        : roots.discriminant > 0 ? extraordinaryRayNormal(roots, 1, std::real(extraordinaryRoot<C>(roots, 1)))
                                 : 0;
    const double rayNormal = twinRayNormal > 0 ? twinRayNormal : dot(incident.ray, N);
    const Wave<double> in[1] = {{incident.mode, k, incident.field, true, rayNormal, dot(k, N)}};
    return fromInside<I>(crystal, incident, in, reflected, kt, N, s, nOutside);
}

// f(C{}, I{}) with the number types of an interface of tangential kt: double for the crystal's waves (C) or
// the outside ones (I) where both of them propagate, by the conditions of the waves' `propagating`.
template <class F>
InterfaceWaves withNumberTypes(const UniaxialMedium& crystal, const ExtraordinaryRoots& roots, const Vec3& kt,
                               double nOutside, F f) {
    const double kt2 = dot(kt, kt);
    const bool crystalReal = crystal.nO * crystal.nO - kt2 > 0 && roots.discriminant > 0;
    if (nOutside * nOutside - kt2 > 0) return crystalReal ? f(double{}, double{}) : f(Complex{}, double{});
    return crystalReal ? f(double{}, Complex{}) : f(Complex{}, Complex{});
}

}  // namespace

InterfaceWaves enterCrystal(const UniaxialMedium& crystal, const Vec3& direction, const Vec3& outwardNormal,
                            double nOutside) {
    checkMedia(crystal, nOutside);
    // Where every wave propagates, the arithmetic the packet walk's lanes share
    // (optics/uniaxial_interface.h).
    const uniaxial::UniaxialEntry<double> entry = uniaxial::enterUniaxial<double>(
        crystal.nO, crystal.nE, crystal.axis, {direction.x, direction.y, direction.z},
        {outwardNormal.x, outwardNormal.y, outwardNormal.z}, nOutside);
    if (std::all_of(std::begin(entry.met), std::end(entry.met), [](bool met) { return met; })) {
        InterfaceWaves out;
        uniaxial::putInterfaceWaves(entry, out);
        return out;
    }
    const Vec3 N = -outwardNormal;  // along the incident energy flow, into the crystal
    const double cosI = dot(direction, N);
    if (!(cosI > 0)) throw Error("birefringence: the light does not travel into the facet");
    const Vec3 kt = (direction - N * cosI) * nOutside;
    const Vec3 s = sDirection(kt, N);
    const ExtraordinaryRoots roots = extraordinaryRoots(crystal, kt, N);
    return withNumberTypes(crystal, roots, kt, nOutside, [&](auto c, auto i) {
        return enterWith<decltype(c), decltype(i)>(crystal, roots, kt, N, s, nOutside);
    });
}

InterfaceWaves leaveCrystal(const UniaxialMedium& crystal, const PlaneWave& incident,
                            const Vec3& outwardNormal, double nOutside) {
    checkMedia(crystal, nOutside);
    const Vec3& N = outwardNormal;  // along the incident energy flow, out of the crystal
    if (incident.mode != WaveMode::Ordinary && incident.mode != WaveMode::Extraordinary)
        throw Error("birefringence: a wave inside the crystal is ordinary or extraordinary");
    // Where the crystal's reflected waves propagate, the arithmetic the packet walk's lanes share
    // (optics/uniaxial_interface.h).
    {
        using uniaxial::V3;
        auto v3 = [](const Vec3& v) { return V3<double>{v.x, v.y, v.z}; };
        const uniaxial::LeavingStart<double> start = uniaxial::startLeaving<double>(
            crystal.nO, crystal.nE, crystal.axis, v3(incident.waveNormal), v3(incident.ray),
            v3(incident.field), incident.index, incident.mode == WaveMode::Ordinary, v3(N), nOutside);
        auto allMet = [](const bool* met, int count) {
            return std::all_of(met, met + count, [](bool m) { return m; });
        };
        if (allMet(start.out.met, start.out.kStartConditions)) {
            const bool evanescent = start.outside2 < 0;
            const uniaxial::UniaxialLeaving<double> w =
                evanescent ? uniaxial::leaveIntoEvanescent(start) : uniaxial::leaveIntoPropagating(start);
            if (allMet(w.met, w.kConditions)) {
                InterfaceWaves out;
                uniaxial::putInterfaceWaves(w, incident, evanescent, out);
                return out;
            }
        }
    }
    const auto [k, kt, s] = insideIncidence(incident, N);
    const ExtraordinaryRoots roots = extraordinaryRoots(crystal, kt, N);
    return withNumberTypes(crystal, roots, kt, nOutside, [&](auto c, auto i) {
        return leaveWith<decltype(c), decltype(i)>(crystal, incident, roots, k, kt, N, s, nOutside);
    });
}

double shareOf(double fluxRatio, Complex ts, Complex tp, const Coherency& j) {
    return shareOfParts(fluxRatio, ts.real(), ts.imag(), tp.real(), tp.imag(), j.ss, j.pp, j.sp.real(),
                        j.sp.imag());
}

// ---- Biaxial crystals (docs/optics.md, "Biaxial crystals") ----
namespace {

// Vectors in the crystal's principal frame (x, y, z), where eps is diag(alpha^2, beta^2, gamma^2).
Vec3 toPrincipal(const BiaxialMedium& m, const Vec3& v) {
    return {dot(m.x, v), dot(m.y, v), dot(m.z, v)};
}
CVec3 toPrincipal(const BiaxialMedium& m, const CVec3& v) {
    return {dot(v, lift<Complex>(m.x)), dot(v, lift<Complex>(m.y)), dot(v, lift<Complex>(m.z))};
}
CVec3 fromPrincipal(const BiaxialMedium& m, const CVec3& v) {
    return lift<Complex>(m.x) * v.x + lift<Complex>(m.y) * v.y + lift<Complex>(m.z) * v.z;
}

// The principal eps_i = n_i^2, u_i = 1 / eps_i and g_i = eps_i (tr eps - eps_i), the diagonal of
// tr(eps) eps - eps^2; and cos Vz, sin Vz, which place the optic axes at (+-sin Vz, 0, cos Vz) (opticAxes).
struct Principal {
    double eps[3], u[3], g[3], det, cosV, sinV;
};
Principal principalOf(const BiaxialMedium& m) {
    Principal p{{m.alpha * m.alpha, m.beta * m.beta, m.gamma * m.gamma}, {}, {}, 0, 0, 0};
    const double trace = p.eps[0] + p.eps[1] + p.eps[2];
    for (int i = 0; i < 3; ++i) {
        p.u[i] = 1 / p.eps[i];
        p.g[i] = p.eps[i] * (trace - p.eps[i]);
    }
    p.det = p.eps[0] * p.eps[1] * p.eps[2];
    // cos^2 Vz = alpha^2 (gamma^2 - beta^2) / (beta^2 (gamma^2 - alpha^2)), the same angle as the tan form.
    const double c2 =
        p.eps[2] > p.eps[0] ? p.eps[0] * (p.eps[2] - p.eps[1]) / (p.eps[1] * (p.eps[2] - p.eps[0])) : 1;
    p.cosV = std::sqrt(c2);
    p.sinV = std::sqrt(std::fmax(0.0, 1 - c2));
    return p;
}
Vec3 fromPrincipal(const BiaxialMedium& m, const Vec3& v) {
    return m.x * v.x + m.y * v.y + m.z * v.z;
}

// The two indices along unit wave normal s (principal frame), the smaller first: Fresnel's equation solved by
// way of the optic axes (Born & Wolf sec. 15.3.3): with theta_1, theta_2 the angles between s and the two
// axes, 1 / n^2 = ((u_x + u_z) + (u_x - u_z) cos(theta_1 -+ theta_2)) / 2. The split, (u_x - u_z) sin theta_1
// sin theta_2, is a product rather than the square root of a difference, so it keeps its precision next to an
// axis (where the quadratic's discriminant cancels); sin theta_i = |s x axis_i|.
std::array<double, 2> indicesAlong(const Principal& p, const Vec3& s) {
    const double c1 = s.x * p.sinV + s.z * p.cosV, c2 = s.z * p.cosV - s.x * p.sinV;
    const double t1 = s.z * p.sinV - s.x * p.cosV, t2 = s.z * p.sinV + s.x * p.cosV, y2 = s.y * s.y;
    const double s1 = std::sqrt(y2 + t1 * t1), s2 = std::sqrt(y2 + t2 * t2);
    const double mean = 0.5 * (p.u[0] + p.u[2]), half = 0.5 * (p.u[0] - p.u[2]);
    return {1 / std::sqrt(mean + half * (c1 * c2 + s1 * s2)),
            1 / std::sqrt(mean + half * (c1 * c2 - s1 * s2))};
}

// The wave matrix k k^T - (k.k) I + eps of a (possibly complex) wave vector in the principal frame: E is its
// null vector (Born & Wolf eq. 15.2.(19) written for E; Yariv & Yeh eq. 4.2-4).
struct CMat3 {
    CVec3 row[3];
};
CMat3 waveMatrix(const Principal& p, const CVec3& k) {
    const Complex kk = dot(k, k), c[3] = {k.x, k.y, k.z};
    CMat3 m;
    CVec3* rows[3] = {&m.row[0], &m.row[1], &m.row[2]};
    for (int i = 0; i < 3; ++i) *rows[i] = CVec3{c[i] * c[0], c[i] * c[1], c[i] * c[2]};
    m.row[0].x += p.eps[0] - kk;
    m.row[1].y += p.eps[1] - kk;
    m.row[2].z += p.eps[2] - kk;
    return m;
}

// The null vector of a wave matrix of rank 2: the largest cross product of two of its rows. `rank2` is false
// when all three are lost in rounding against the rows (a double root: the wave normal on an optic axis).
CVec3 nullVector(const CMat3& m, bool& rank2) {
    const CVec3 c[3] = {cross(m.row[0], m.row[1]), cross(m.row[0], m.row[2]), cross(m.row[1], m.row[2])};
    int best = 0;
    for (int i = 1; i < 3; ++i)
        if (norm2(c[i]) > norm2(c[best])) best = i;
    double rowMax = 0;
    for (const CVec3& r : m.row) rowMax = std::fmax(rowMax, norm2(r));
    rank2 = norm2(c[best]) > 1e-20 * rowMax * rowMax;
    return c[best];
}

// Two fields spanning the null space of a wave matrix of rank 1 (two degenerate waves): `reference` with its
// part along the matrix's largest row r taken out, and r x that. A symmetric matrix of rank 1 is a multiple
// of r r^T, whose null space is everything across r.
void degeneratePair(const CMat3& m, const CVec3& reference, CVec3& e1, CVec3& e2) {
    int best = 0;
    for (int i = 1; i < 3; ++i)
        if (norm2(m.row[i]) > norm2(m.row[best])) best = i;
    const CVec3& r = m.row[best];
    e1 = reference - r * (dot(r, reference) / dot(r, r));
    if (!(norm2(e1) > 1e-12 * norm2(reference))) {  // the reference along r: any other direction
        const Vec3 q = perpendicularTo(normalize(realPart(r)));
        e1 = CVec3{q.x, q.y, q.z};
    }
    e2 = cross(r, e1);
}

// The largest real root of the monic cubic m^3 + b m^2 + c m + d (Numerical Recipes, 3rd ed., sec. 5.6:
// the trigonometric form for three real roots, Cardano's with the cancellation-free sign choice for one).
double largestCubicRoot(double b, double c, double d) {
    const double Q = (b * b - 3 * c) * (1.0 / 9), R = (2 * b * b * b - 9 * b * c + 27 * d) * (1.0 / 54);
    const double Q3 = Q * Q * Q;
    if (R * R < Q3) {
        const double theta = std::acos(std::clamp(R / std::sqrt(Q3), -1.0, 1.0));
        return -2 * std::sqrt(Q) * std::cos((theta + 6.283185307179586) * (1.0 / 3)) - b * (1.0 / 3);
    }
    const double A = -std::copysign(std::cbrt(std::fabs(R) + std::sqrt(R * R - Q3)), R);
    return A + (A != 0 ? Q / A : 0) - b * (1.0 / 3);
}

// The roots of y^2 + b y + c, the real ones without cancellation.
void quadraticRoots(double b, double c, Complex y[2]) {
    const double disc = b * b - 4 * c;
    if (disc >= 0) {
        const double t = -0.5 * (b + std::copysign(std::sqrt(disc), b));
        y[0] = t;
        y[1] = t != 0 ? c / t : 0;
    } else {
        const double im = 0.5 * std::sqrt(-disc);
        y[0] = Complex(-0.5 * b, im);
        y[1] = Complex(-0.5 * b, -im);
    }
}

// Ferrari's closed form in real arithmetic: the depressed quartic y^4 + p y^2 + r y + s (z = y - A / 4) is
// (y^2 + alpha y + m - beta)(y^2 - alpha y + m + beta) with m the resolvent cubic's largest root,
// alpha^2 = 2 m - p >= 0, beta^2 = m^2 - s and 2 alpha beta = r; of alpha and beta the one whose square
// cancels less is taken from its square, the other from r (Abramowitz & Stegun 3.8.3; the two-quadratic form
// as in Strobach, J. Comput. Appl. Math. 234, 3007, 2010). Its rounding is then removed by the iteration.
void ferrariRoots(const double c[5], Complex z[4]) {
    const double inverse = 1 / c[4];
    const double A = c[3] * inverse, B = c[2] * inverse, C = c[1] * inverse, D = c[0] * inverse;
    const double A2 = A * A;
    const double p = B - 0.375 * A2, r = C - 0.5 * A * B + 0.125 * A2 * A,
                 s = D - 0.25 * A * C + 0.0625 * A2 * B - 0.01171875 * A2 * A2;
    const double m = largestCubicRoot(-0.5 * p, -s, 0.5 * p * s - 0.125 * r * r);
    const double alpha2 = 2 * m - p > 0 ? 2 * m - p : 0, beta2 = m * m - s > 0 ? m * m - s : 0;
    double alpha = 0, beta = 0;
    if (alpha2 * (m * m + std::fabs(s)) >= beta2 * (2 * std::fabs(m) + std::fabs(p))) {
        alpha = std::sqrt(alpha2);
        beta = alpha > 0 ? r / (2 * alpha) : 0;
    } else {
        beta = std::copysign(std::sqrt(beta2), r);
        alpha = r / (2 * beta);
    }
    quadraticRoots(alpha, m - beta, z);
    quadraticRoots(-alpha, m + beta, z + 2);
    for (int j = 0; j < 4; ++j) z[j] -= 0.25 * A;
}

// Newton's iteration on the quartic c from z (real or complex) until its step is at rounding (the tests of the
// Aberth iteration below), at most 8 steps; false if it did not get there.
template <class T>
bool newtonRoot(const double c[5], double scale, T& z) {
    double previous = INFINITY;
    for (int iteration = 0; iteration < 8; ++iteration) {
        const T p = (((c[4] * z + c[3]) * z + c[2]) * z + c[1]) * z + c[0];
        const T dp = ((4 * c[4] * z + 3 * c[3]) * z + 2 * c[2]) * z + c[1];
        if (p == 0.0) return true;
        const T step = p / dp;
        if (!(std::isfinite(std::real(step)) && std::isfinite(std::imag(step)))) return false;
        z -= step;
        const double size = std::norm(step), s2 = scale * scale;
        if (size <= 1e-28 * s2 || (size <= 1e-18 * s2 && size >= 0.25 * previous)) return true;
        previous = size;
    }
    return false;
}

// Ferrari's roots of the quartic c[4] z^4 + ... + c[0] (c[4] != 0), and whether they are finite and lie at
// least 1e-4 scale apart: then Newton's iteration refines each one it is asked for (refinedRoot) and cannot
// slip to a neighbour (Ferrari's error is far smaller), and only the roots kept need it. Else
// aberthRoots refines them together.
bool separatedRoots(const double c[5], double scale, Complex z[4]) {
    ferrariRoots(c, z);
    bool finite = true;
    double gap = INFINITY;
    for (int j = 0; j < 4; ++j) {
        finite = finite && std::isfinite(z[j].real()) && std::isfinite(z[j].imag());
        for (int l = j + 1; l < 4; ++l) {
            const double d = std::norm(z[j] - z[l]);
            gap = d < gap ? d : gap;
        }
    }
    return finite && gap >= 1e-8 * scale * scale;
}

// Root j of separatedRoots' z refined by Newton's iteration: a real one in real arithmetic, a complex one as
// the conjugate of its pair's first (quadraticRoots gives a complex pair as z[0], z[1] or z[2], z[3], the
// first with Im > 0). False if it did not converge.
bool refinedRoot(const double c[5], double scale, const Complex z[4], int j, Complex& root) {
    if (z[j].imag() != 0) {
        Complex first = z[j & ~1];
        const bool converged = newtonRoot(c, scale, first);
        root = j & 1 ? std::conj(first) : first;
        return converged;
    }
    double x = z[j].real();
    const bool converged = newtonRoot(c, scale, x);
    root = x;
    return converged;
}

// The quartic's roots by the Aberth-Ehrlich iteration (Aberth, Math. Comp. 27, 339, 1973) from Ferrari's
// roots z, which keeps close roots apart (it converges from any start for simple roots: from the circle of
// radius `scale`, which bounds the roots, should Ferrari's fail). Fixed-size, no allocation, the same steps
// for the same coefficients.
void aberthRoots(const double c[5], double scale, Complex z[4]) {
    bool finite = true;
    for (int j = 0; j < 4; ++j) finite = finite && std::isfinite(z[j].real()) && std::isfinite(z[j].imag());
    if (!finite)
        for (int l = 0; l < 4; ++l) z[l] = std::polar(scale, 0.4 + l * 1.5707963267948966);
    // Done when the steps are at rounding, or small and no longer shrinking (close roots, whose rounding
    // floor lies above the first test). Squared magnitudes: no hypot.
    double previous = INFINITY;
    for (int iteration = 0, quiet = 0; iteration < 200 && quiet < 2; ++iteration) {
        double largest = 0;
        for (int j = 0; j < 4; ++j) {
            const Complex x = z[j];
            const Complex p = (((c[4] * x + c[3]) * x + c[2]) * x + c[1]) * x + c[0];
            const Complex dp = ((4 * c[4] * x + 3 * c[3]) * x + 2 * c[2]) * x + c[1];
            if (p == 0.0) continue;
            Complex sum = 0;
            for (int l = 0; l < 4; ++l)
                if (l != j) sum += 1.0 / (x - z[l]);
            const Complex ratio = p / dp;
            const Complex w = ratio / (1.0 - ratio * sum);
            if (!(std::isfinite(w.real()) && std::isfinite(w.imag()))) continue;
            z[j] = x - w;
            largest = std::fmax(largest, std::norm(w));
        }
        const double s2 = scale * scale;
        const bool atFloor = largest <= 1e-28 * s2 || (largest <= 1e-18 * s2 && largest >= 0.25 * previous);
        quiet = atFloor ? quiet + 1 : 0;
        previous = largest;
    }
}

// E = eps^-1 D of a propagating wave along unit wave normal kHat (principal frame), D being an eigenvector of
// eps^-1 restricted to the plane across kHat, the larger eigenvalue 1 / n^2 (the smaller index) for Fast
// (Born & Wolf sec. 15.2.2: the index ellipsoid's section). A 2x2 symmetric eigenproblem stays well
// conditioned where the two indices nearly agree (a weakly birefringent crystal, a wave normal near an optic
// axis), unlike the null vector of the wave matrix; on an optic axis it still gives an orthogonal pair. The
// eigenvector's angle theta = atan2(2 b, a - c) / 2 for the form [[a, b], [b, c]]: by the half-angle formulas
// (cos theta, sin theta) lies along (h + x, y) and along sign(y) (y, h - x), x = a - c, y = 2 b,
// h = sqrt(x^2 + y^2), each taken where it does not cancel. E comes unnormalised (of any length, not zero):
// its callers normalise it, so no square root and division here do it for the angle.
Vec3 fieldOf(const Principal& p, const Vec3& kHat, bool slow) {
    const Vec3 e1 = perpendicularTo(kHat), e2 = cross(kHat, e1);
    auto form = [&](const Vec3& a, const Vec3& b) {
        return p.u[0] * a.x * b.x + p.u[1] * a.y * b.y + p.u[2] * a.z * b.z;
    };
    const double x = form(e1, e1) - form(e2, e2), y = 2 * form(e1, e2), h = std::sqrt(x * x + y * y);
    double c = 1, sn = 0;  // theta = 0 on an optic axis (h = 0), as atan2(0, 0) gives
    if (h > 0 && x >= 0) {
        c = h + x;
        sn = y;
    } else if (h > 0) {
        c = std::fabs(y);
        sn = std::copysign(h - x, y);
    }
    const Vec3 d = slow ? e2 * c - e1 * sn : e1 * c + e2 * sn;
    return {d.x * p.u[0], d.y * p.u[1], d.z * p.u[2]};
}

// The interface in the crystal's principal frame: the medium, its principal values, kt (u) and N (n).
struct Setting {
    const BiaxialMedium& m;
    Principal pr;
    Vec3 u, n;
};

// A real root q of the quartic on its sheet of the index surface (principal frame): k = u + q n, |k|, k / |k|
// and the index along it on the sheet whose index is nearer |k| (a line of fixed kt may cross either sheet
// twice, the outer one being dimpled at the optic axes); once given a field (setField), its ray, the ray's
// normal component and the wave in the stone's frame.
struct SheetPoint {
    double q = 0;
    Vec3 kHat, ray;
    double nk = 0, index = 0, rayNormal = 0;
    bool slowSheet = false, nearAxis = false;
    KnownWave known{};
};

void locate(const Setting& b, SheetPoint& p, bool classify) {
    const Vec3 k = b.u + b.n * p.q;
    p.nk = length(k);
    p.kHat = k * (1 / p.nk);
    const std::array<double, 2> indices = indicesAlong(b.pr, p.kHat);
    if (classify) {
        p.slowSheet = std::fabs(p.nk - indices[1]) < std::fabs(p.nk - indices[0]);
        p.nearAxis = indices[1] - indices[0] <= 1e-6 * p.nk;
    }
    p.index = indices[p.slowSheet ? 1 : 0];
}

// The field of the Fast or Slow wave along p's wave normal (the eigenproblem), its ray and the wave.
void setField(const Setting& b, SheetPoint& p, bool slow) {
    const Vec3 k = b.u + b.n * p.q;
    p.nk = length(k);
    p.kHat = k * (1 / p.nk);
    // The flux E x (k x E) of the unit E along f, k - f (f.k) / f.f, not waiting for E.
    const Vec3 f = fieldOf(b.pr, p.kHat, slow);
    const double ff = dot(f, f);
    const Vec3 e = f * (1 / std::sqrt(ff));
    const Vec3 flux = k - f * (dot(f, k) / ff);
    const double fluxLength = length(flux);
    p.ray = flux * (1 / fluxLength);
    p.rayNormal = dot(p.ray, b.n);
    p.known.wave.field = fromPrincipal(b.m, e);
    p.known.wave.waveNormal = fromPrincipal(b.m, p.kHat);
    p.known.wave.ray = fromPrincipal(b.m, p.ray);
    p.known.wave.index = p.nk;
    p.known.flux = fluxLength * p.rayNormal;
}

// Newton's step along N onto p's sheet, |k| = n(k / |k|): that function's gradient is the ray t over
// t.k/|k|, t along the ray or the gradient of F. Its sheets part where two roots of the quartic nearly meet
// (a weak birefringence, an axis close by), which the quartic's own rounding does not resolve.
double sheetStep(const Setting& b, SheetPoint& p, const Vec3& t) {
    const double step = (p.nk - p.index) * dot(t, p.kHat) / dot(t, b.n);
    p.q -= step;
    return step;
}

// From a located root of the quartic, the step onto its sheet along F's gradient: at its rounding, or a
// second where the first was larger.
void polishOntoSheet(const Setting& b, SheetPoint& p) {
    const Principal& pr = b.pr;
    for (int polish = 0; polish < 2; ++polish) {
        const Vec3 k = b.u + b.n * p.q;
        const double kk = dot(k, k),
                     kEpsK = pr.eps[0] * k.x * k.x + pr.eps[1] * k.y * k.y + pr.eps[2] * k.z * k.z;
        const Vec3 gradient =
            Vec3{k.x * (kEpsK + kk * pr.eps[0] - pr.g[0]), k.y * (kEpsK + kk * pr.eps[1] - pr.g[1]),
                 k.z * (kEpsK + kk * pr.eps[2] - pr.g[2])};
        if (std::fabs(sheetStep(b, p, gradient)) <= 1e-13 * p.nk || polish == 1) break;
        locate(b, p, false);
    }
}

// The wave of a propagating root, its field set.
Wave<Complex> crystalWave(const SheetPoint& p, const Vec3& kt, const Vec3& N) {
    return {WaveMode::Fast,
            lift<Complex>(kt) + lift<Complex>(N) * Complex(p.q),
            lift<Complex>(p.known.wave.field),
            true,
            p.rayNormal,
            p.q};
}

// The crystal's two waves from the kept roots fast and slow (Fast first: the smaller k.k, an evanescent
// wave's q^2 having a negative real part); two next to an optic axis on the same sheet are the degenerate
// pair, one field each.
void putWaves(const Setting& b, Wave<Complex> w[], SheetPoint at[], int fast, int slow, const Vec3& kt,
              const Vec3& N, Wave<Complex> out[2], KnownWave known[2]) {
    if ((w[slow].q * w[slow].q).real() < (w[fast].q * w[fast].q).real()) std::swap(fast, slow);
    if (at[fast].nearAxis && at[slow].nearAxis && at[fast].slowSheet == at[slow].slowSheet) {
        setField(b, at[fast], false);
        setField(b, at[slow], true);
        w[fast] = crystalWave(at[fast], kt, N);
        w[slow] = crystalWave(at[slow], kt, N);
    }
    out[0] = w[fast];
    out[1] = w[slow];
    out[0].mode = WaveMode::Fast;
    out[1].mode = WaveMode::Slow;
    known[0] = at[fast].known;
    known[1] = at[slow].known;
    known[0].wave.mode = WaveMode::Fast;
    known[1].wave.mode = WaveMode::Slow;
}

// The common case of biaxialWaves: four real roots far apart, a line through nested sheets. Of the roots in
// order, the line enters the outer sheet, the inner (fast) one, leaves the inner and then the outer, so the
// outermost root of `side` is kept (on the outer sheet) and with it the middle one if it lies on the inner
// sheet (else the line misses the inner sheet, crossing the outer one's dimples: biaxialWaves' general way).
// The two are refined, located and given fields side by side, their arithmetic independent. False where
// this does not apply.
bool nestedWaves(const Setting& b, const double c[5], double scale, const Complex z[4], int side,
                 const Vec3& kt, const Vec3& N, Wave<Complex> out[2], KnownWave known[2]) {
    double r[4];
    for (int j = 0; j < 4; ++j) {
        if (z[j].imag() != 0) return false;
        r[j] = z[j].real();
    }
    std::sort(r, r + 4);
    SheetPoint at[2];  // the middle root, the outermost
    at[0].q = side > 0 ? r[2] : r[1];
    at[1].q = side > 0 ? r[3] : r[0];
    const bool converged[2] = {newtonRoot(c, scale, at[0].q), newtonRoot(c, scale, at[1].q)};
    if (!(converged[0] && converged[1])) return false;
    for (SheetPoint& p : at) locate(b, p, true);
    if (at[0].slowSheet) return false;
    for (SheetPoint& p : at) polishOntoSheet(b, p);
    for (SheetPoint& p : at) setField(b, p, p.slowSheet);
    Wave<Complex> w[2] = {crystalWave(at[0], kt, N), crystalWave(at[1], kt, N)};
    // Kept in the roots' order along N, the first the one biaxialWaves' general way would take as Fast.
    putWaves(b, w, at, side > 0 ? 0 : 1, side > 0 ? 1 : 0, kt, N, out, known);
    return true;
}

// The biaxial crystal's two waves of tangential kt whose energy leaves the facet along side * N, Fast then
// Slow, with fields (unit where the wave propagates, else unnormalised) and for a propagating one its ray's
// normal component and, in known[], its PlaneWave and flux. The quartic
// det(k k^T - (k.k) I + eps) = 0 for k = kt + q N, with eps and G = tr(eps) eps - eps^2 in the principal
// frame, is F(k) = (k.k)(k.eps.k) - k.G.k + det eps = 0 (Fresnel's equation of wave normals multiplied out);
// its four roots are two on each side: a real root by the sign of its Poynting flux along N, E x (k x E), a
// complex one (evanescent) by the side it decays on. Only the two kept are refined and given fields.
void biaxialWaves(const BiaxialMedium& m, const Vec3& kt, const Vec3& N, const Vec3& s, int side,
                  Wave<Complex> out[2], KnownWave known[2], double qIncident = NAN) {
    const Setting b{m, principalOf(m), toPrincipal(m, kt), toPrincipal(m, N)};
    const Principal& pr = b.pr;
    const Vec3 &u = b.u, &n = b.n;
    auto form = [&](const double* d, const Vec3& a, const Vec3& v) {
        return d[0] * a.x * v.x + d[1] * a.y * v.y + d[2] * a.z * v.z;
    };
    const double u2 = dot(kt, kt);
    const double a0 = form(pr.eps, u, u), a1 = form(pr.eps, u, n), a2 = form(pr.eps, n, n);
    const double g0 = form(pr.g, u, u), g1 = form(pr.g, u, n), g2 = form(pr.g, n, n);
    const double c[5] = {u2 * a0 - g0 + pr.det, 2 * (u2 * a1 - g1), a0 + u2 * a2 - g2, 2 * a1, a2};
    Complex q[4];
    const double scale = m.gamma + std::sqrt(u2);
    const bool separated = separatedRoots(c, scale, q);
    if (separated && nestedWaves(b, c, scale, q, side, kt, N, out, known)) return;

    Wave<Complex> w[4];
    SheetPoint at[4];
    // Root j at r: its wave vector, and whether it propagates.
    auto place = [&](int j, Complex r) {
        q[j] = w[j].q = r;
        w[j].k = lift<Complex>(kt) + lift<Complex>(N) * r;
        w[j].propagating = r.imag() == 0;
        at[j].q = r.real();
    };
    // A propagating root's wave once its field is set.
    auto putField = [&](int j) {
        w[j].field = lift<Complex>(at[j].known.wave.field);
        w[j].rayNormal = at[j].rayNormal;
    };
    auto putStep = [&](int j) {
        w[j].q = at[j].q;
        w[j].k = lift<Complex>(kt) + lift<Complex>(N) * w[j].q;
    };
    for (int j = 0; j < 4; ++j) place(j, q[j]);
    int kept[2];
    auto keepSeparated = [&]() {
        // Roots far apart, each simple: a line crosses a closed sheet entering it then leaving, so of the
        // real roots in order, the sheets nested (the inner one the fast sheet), the last two leave along
        // +N and the first two along -N; a line that misses the inner sheet and crosses the outer one four
        // times through its dimples leaves at the second and fourth. Two real roots: entering, then leaving.
        // Ferrari's roots order and classify them as well as the refined ones would; only the kept ones (and
        // the middle one that tells the sheets apart) are refined, each as a root of the whole quartic, and
        // should one not converge the roots are refined together (aberthRoots) and the close roots' way
        // taken.
        const Complex ferrari[4] = {q[0], q[1], q[2], q[3]};
        auto refine = [&](int j) {
            Complex r;
            const bool converged = refinedRoot(c, scale, ferrari, j, r);
            place(j, r);
            return converged;
        };
        int real[4], count = 0, decaying = -1;
        for (int j = 0; j < 4; ++j) {
            if (w[j].propagating)
                real[count++] = j;
            else if (side * q[j].imag() > 0)
                kept[decaying < 0 ? 0 : 1] = j, decaying = j;
        }
        for (int i = 1; i < count; ++i)  // in order of q
            for (int l = i; l > 0 && q[real[l]].real() < q[real[l - 1]].real(); --l)
                std::swap(real[l], real[l - 1]);
        if (count == 2) kept[1] = side > 0 ? real[1] : real[0];
        if (count == 4) {
            const int middle = side > 0 ? real[2] : real[1];
            if (!refine(middle)) return false;
            locate(b, at[middle], true);
            const bool nested = !at[middle].slowSheet;
            kept[0] = side > 0 ? real[nested ? 2 : 1] : real[0];
            kept[1] = side > 0 ? real[3] : real[nested ? 1 : 2];
        }
        for (int j : kept) {
            const bool middle = count == 4 && j == (side > 0 ? real[2] : real[1]);
            if (!middle && !refine(j)) return false;
        }
        for (int j : kept) {
            if (!w[j].propagating) continue;
            if (count < 4 || j != (side > 0 ? real[2] : real[1])) locate(b, at[j], true);
            polishOntoSheet(b, at[j]);
            putStep(j);
            setField(b, at[j], at[j].slowSheet);
            putField(j);
        }
        return true;
    };
    if (!(separated && keepSeparated())) {
        if (separated) {  // a kept root did not converge: start afresh from Ferrari's roots
            ferrariRoots(c, q);
            for (SheetPoint& p : at) p = SheetPoint{};
        }
        aberthRoots(c, scale, q);
        for (Complex& r : q)
            if (std::fabs(r.imag()) <= 1e-9 * scale) r = r.real();
        // A double root (a wave normal on an optic axis) comes out as two roots about sqrt(rounding) apart on
        // either side of it, along the real axis or across it (a pair with imaginary parts of that size,
        // which would pass for evanescent waves): their mean's real part is the root to rounding.
        for (int j = 0; j < 4; ++j)
            for (int l = j + 1; l < 4; ++l)
                if (std::norm(q[j] - q[l]) <= 1e-14 * scale * scale &&
                    std::fabs(q[j].imag()) <= 1e-7 * scale && std::fabs(q[l].imag()) <= 1e-7 * scale)
                    q[j] = q[l] = 0.5 * (q[j].real() + q[l].real());
        // Leaving, the incident wave is a real root at qIncident, and next to an optic axis its twin on the
        // other sheet lies a few tenths of a millionth from it: rounding may turn the two into a complex pair
        // around them. They are the incident wave and its twin, not evanescent waves, and not among the
        // reflected waves sought: both are put at qIncident, on the incident side.
        if (!std::isnan(qIncident))
            for (int j = 0; j < 4; ++j)
                for (int l = j + 1; l < 4; ++l) {
                    const double near = std::fmax(1e-6 * scale, 2 * std::fabs(q[j].imag()));
                    if (q[j].imag() != 0 && std::fabs(q[j].imag()) <= 1e-5 * scale &&
                        std::fabs(q[j].real() - qIncident) <= near &&
                        std::fabs(q[l].real() - qIncident) <= near) {
                        q[j] = q[l] = qIncident;
                    }
                }
        for (int j = 0; j < 4; ++j) place(j, q[j]);
        // Roots close together: each real root's side from its field's Poynting flux.
        double score[4];
        for (int j = 0; j < 4; ++j) {
            score[j] = q[j].imag() > 0 ? 2 : -2;
            if (!w[j].propagating) continue;
            locate(b, at[j], true);
            setField(b, at[j], at[j].slowSheet);
            putField(j);
            score[j] = w[j].rayNormal;
        }
        // The two roots of `side`: the largest scores side * score.
        int order[4] = {0, 1, 2, 3};
        std::sort(order, order + 4, [&](int a, int b) { return side * score[a] > side * score[b]; });
        kept[0] = order[0];
        kept[1] = order[1];
        for (int j : kept) {
            if (!w[j].propagating) continue;
            for (int polish = 0; polish < 2 && std::fabs(w[j].rayNormal) > 1e-6; ++polish) {
                if (polish == 1) locate(b, at[j], false);
                const double step = sheetStep(b, at[j], at[j].ray);
                putStep(j);
                if (step == 0) break;  // the same root, field and ray again
                setField(b, at[j], at[j].slowSheet);
                putField(j);
            }
        }
    }
    for (int j : kept) {
        if (w[j].propagating) continue;
        const CMat3 mat = waveMatrix(pr, toPrincipal(m, w[j].k));
        bool rank2;
        CVec3 e = nullVector(mat, rank2), e2;
        if (!rank2) degeneratePair(mat, toPrincipal(m, lift<Complex>(s)), e, e2);
        w[j].field = fromPrincipal(m, e);
        w[j].rayNormal = 0;
    }
    putWaves(b, w, at, kept[0], kept[1], kt, N, out, known);
}

template <class T>
Wave<T> narrowed(const Wave<Complex>& w) {
    if constexpr (std::is_same_v<T, double>) {
        return {w.mode, realPart(w.k), realPart(w.field), w.propagating, w.rayNormal, w.q.real()};
    } else {
        return w;
    }
}

void checkMedia(const BiaxialMedium& m, double nOutside) {
    if (!(m.alpha > 0 && m.alpha <= m.beta && m.beta <= m.gamma && nOutside > 0))
        throw Error("birefringence: a biaxial crystal needs 0 < alpha <= beta <= gamma");
    const bool orthonormal = std::fabs(dot(m.x, m.x) - 1) < 1e-9 && std::fabs(dot(m.y, m.y) - 1) < 1e-9 &&
                             std::fabs(dot(m.z, m.z) - 1) < 1e-9 && std::fabs(dot(m.x, m.y)) < 1e-9 &&
                             std::fabs(dot(m.x, m.z)) < 1e-9 && std::fabs(dot(m.y, m.z)) < 1e-9;
    if (!orthonormal) throw Error("birefringence: a biaxial crystal's principal axes must be orthonormal");
}

// f(C{}, I{}) as withNumberTypes: double for the crystal's waves (C) or the outside ones (I) where both
// propagate.
template <class F>
InterfaceWaves withTypes(bool crystalReal, bool outsideReal, F f) {
    if (outsideReal) return crystalReal ? f(double{}, double{}) : f(Complex{}, double{});
    return crystalReal ? f(double{}, Complex{}) : f(Complex{}, Complex{});
}

}  // namespace

std::array<Vec3, 2> opticAxes(const BiaxialMedium& m) {
    const Principal p = principalOf(m);
    return {m.z * p.cosV + m.x * p.sinV, m.z * p.cosV - m.x * p.sinV};
}

std::array<double, 2> waveIndices(const BiaxialMedium& medium, const Vec3& waveNormal) {
    return indicesAlong(principalOf(medium), toPrincipal(medium, waveNormal));
}

PlaneWave biaxialWave(const BiaxialMedium& medium, const Vec3& waveNormal, WaveMode mode) {
    checkMedia(medium, 1);
    if (mode != WaveMode::Fast && mode != WaveMode::Slow)
        throw Error("birefringence: a biaxial crystal's waves are Fast and Slow");
    const bool slow = mode == WaveMode::Slow;
    const Vec3 k = waveNormal * waveIndices(medium, waveNormal)[slow ? 1 : 0];
    const Vec3 e = fieldOf(principalOf(medium), toPrincipal(medium, waveNormal), slow);
    const Wave<double> w{mode, k, fromPrincipal(medium, e), true, 0, 0};
    return toPlaneWave(&medium, w);
}

InterfaceWaves enterCrystal(const BiaxialMedium& crystal, const Vec3& direction, const Vec3& outwardNormal,
                            double nOutside) {
    checkMedia(crystal, nOutside);
    const Vec3 N = -normalize(outwardNormal);  // a unit N: the quartic's k.k = kt.kt + q^2 takes it so
    const double cosI = dot(direction, N);
    if (!(cosI > 0)) throw Error("birefringence: the light does not travel into the facet");
    const Vec3 kt = (direction - N * cosI) * nOutside;
    const Vec3 s = sDirection(kt, N);
    Wave<Complex> waves[2];
    KnownWave known[2];
    biaxialWaves(crystal, kt, N, s, 1, waves, known);
    const bool crystalReal = waves[0].propagating && waves[1].propagating;
    return withTypes(crystalReal, nOutside * nOutside - dot(kt, kt) > 0, [&](auto c, auto i) {
        using C = decltype(c);
        const Wave<C> transmitted[2] = {narrowed<C>(waves[0]), narrowed<C>(waves[1])};
        return fromOutside<decltype(i)>(crystal, transmitted, kt, N, s, nOutside, known);
    });
}

InterfaceWaves leaveCrystal(const BiaxialMedium& crystal, const PlaneWave& incident,
                            const Vec3& outwardNormal, double nOutside) {
    checkMedia(crystal, nOutside);
    // A unit N, as the quartic takes it (k.k = kt.kt + q^2): a float facet normal off unit length by 1e-7
    // moved the roots near a double one by 1e-4 (the square root), even into a complex pair.
    const Vec3 N = normalize(outwardNormal);
    if (incident.mode != WaveMode::Fast && incident.mode != WaveMode::Slow)
        throw Error("birefringence: a wave inside a biaxial crystal is Fast or Slow");
    const auto [k, kt, s] = insideIncidence(incident, N);
    Wave<Complex> waves[2];
    KnownWave known[2];
    biaxialWaves(crystal, kt, N, s, -1, waves, known, dot(k, N));
    const bool crystalReal = waves[0].propagating && waves[1].propagating;
    const Wave<double> in[1] = {{incident.mode, k, incident.field, true, dot(incident.ray, N), dot(k, N)}};
    return withTypes(crystalReal, nOutside * nOutside - dot(kt, kt) > 0, [&](auto c, auto i) {
        using C = decltype(c);
        const Wave<C> reflected[2] = {narrowed<C>(waves[0]), narrowed<C>(waves[1])};
        return fromInside<decltype(i)>(crystal, incident, in, reflected, kt, N, s, nOutside, known);
    });
}

}  // namespace facetlight
