#include "optics/birefringence.h"

#include <cmath>

#include "util/error.h"

namespace facetlight {
namespace {

// A complex 3-vector. Products are bilinear (no conjugation) as in Maxwell's equations for complex k; the
// Hermitian norm only scales evanescent fields, whose scale carries no energy.
struct CVec3 {
    Complex x, y, z;
};

CVec3 toComplex(const Vec3& v) {
    return {v.x, v.y, v.z};
}
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

// Any unit vector perpendicular to unit n (Duff et al., "Building an orthonormal basis, revisited", 2017).
Vec3 perpendicularTo(const Vec3& n) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1 / (sign + n.z);
    return {1 + sign * n.x * n.x * a, sign * n.x * n.y * a, -sign * n.x};
}

// Below this |k x c| / |k| the wave normal counts as along the axis, where the ordinary and extraordinary
// waves are degenerate and k x c no longer fixes a direction.
constexpr double kAlongAxis = 1e-9;

// eps^-1 v for eps = n_o^2 I + (n_e^2 - n_o^2) c c^T.
CVec3 inverseEpsilonTimes(const UniaxialMedium& m, const CVec3& v) {
    const double io = 1 / (m.nO * m.nO), ie = 1 / (m.nE * m.nE);
    const CVec3 c = toComplex(m.axis);
    return v * io + c * (dot(c, v) * (ie - io));
}
Vec3 epsilonTimes(const UniaxialMedium& m, const Vec3& v) {
    return v * (m.nO * m.nO) + m.axis * (dot(m.axis, v) * (m.nE * m.nE - m.nO * m.nO));
}

// E of the ordinary wave of (possibly complex) wave vector k: along k x c, perpendicular to the axis and to k
// (Born & Wolf ch. 15). Along the axis, the part of `reference` perpendicular to the axis.
CVec3 ordinaryField(const UniaxialMedium& m, const CVec3& k, const Vec3& reference) {
    const CVec3 e = cross(k, toComplex(m.axis));
    if (norm2(e) > kAlongAxis * kAlongAxis * norm2(k)) return e;
    return toComplex(reference - m.axis * dot(m.axis, reference));
}

// E of the extraordinary wave: D lies in the plane of k and c, perpendicular to k, D ~ c (k.k) - k (k.c), and
// E = eps^-1 D (Yariv & Yeh ch. 4). Along the axis, k x E_o.
CVec3 extraordinaryField(const UniaxialMedium& m, const CVec3& k, const Vec3& reference) {
    const CVec3 c = toComplex(m.axis);
    const CVec3 d = c * dot(k, k) - k * dot(k, c);
    if (norm2(d) > kAlongAxis * kAlongAxis * norm2(k) * norm2(k)) return inverseEpsilonTimes(m, d);
    return cross(k, ordinaryField(m, k, reference));
}

// One wave of the interface problem: its wave vector and field (complex when evanescent), and for a
// propagating wave the normal component of its unit ray direction. That component is taken from the root
// (q / n, or sqrt(b^2 - a c) / |eps k|) rather than from the vectors: near grazing it is small, and the
// incident and the reflected wave of the same kind then carry exactly opposite fluxes, which keeps energy
// conserved to rounding there too.
struct Wave {
    WaveMode mode;
    CVec3 k;
    CVec3 field;
    bool propagating;
    double rayNormal;
    Complex q;  // N . k
};

// The principal square root of a real x, as std::sqrt(Complex(x, +0)) gives it, without the complex call.
Complex principalRoot(double x) {
    return x >= 0 ? Complex(std::sqrt(x), 0) : Complex(0, std::sqrt(-x));
}

// The normal component q of the wave vector kt + q N of each outgoing wave. `side` is +1 for the waves whose
// energy leaves along +N (transmitted), -1 for those leaving along -N (reflected); an evanescent wave must
// decay on its side, Im(q) side > 0. For |k|^2 = n^2: q = side sqrt(n^2 - kt^2), the flux is along k. For the
// extraordinary wave, k.eps.k = n_o^2 n_e^2 is the quadratic a q^2 + 2 b q + c = 0 with a = N.eps.N,
// b = kt.eps.N, c = kt.eps.kt - n_o^2 n_e^2; its ray is along eps k (the normal to the index surface), whose
// normal component is b + a q = +-sqrt(b^2 - a c): the root with +sqrt sends energy along +N whichever way
// its wave normal points. The principal complex square root gives the decaying root for either side.
Wave isotropicWave(WaveMode mode, double n, const Vec3& kt, const Vec3& N, const Vec3& s, int side) {
    const Complex q = double(side) * principalRoot(n * n - dot(kt, kt));
    const CVec3 k = toComplex(kt) + toComplex(N) * q;
    const bool propagating = n * n - dot(kt, kt) > 0;
    const CVec3 field = mode == WaveMode::S ? toComplex(s) : cross(k, toComplex(s)) * (1 / n);
    return {mode, k, field, propagating, propagating ? q.real() / n : 0, q};
}

Wave ordinaryInterfaceWave(const UniaxialMedium& m, const Vec3& kt, const Vec3& N, const Vec3& s, int side) {
    const double q2 = m.nO * m.nO - dot(kt, kt);
    const Complex q = double(side) * principalRoot(q2);
    const CVec3 k = toComplex(kt) + toComplex(N) * q;
    return {WaveMode::Ordinary, k, ordinaryField(m, k, s), q2 > 0, q2 > 0 ? q.real() / m.nO : 0, q};
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
Complex extraordinaryRoot(const ExtraordinaryRoots& r, int side) {
    return (-r.b + double(side) * principalRoot(r.discriminant)) / r.a;
}
double extraordinaryRayNormal(const ExtraordinaryRoots& r, int side, double q) {
    return side * std::sqrt(r.discriminant) / length(r.epsKt + r.epsN * q);
}

Wave extraordinaryInterfaceWave(const UniaxialMedium& m, const ExtraordinaryRoots& r, const Vec3& kt,
                                const Vec3& N, const Vec3& s, int side) {
    const Complex q = extraordinaryRoot(r, side);
    const CVec3 k = toComplex(kt) + toComplex(N) * q;
    const bool propagating = r.discriminant > 0;
    const double rayNormal = propagating ? extraordinaryRayNormal(r, side, q.real()) : 0;
    return {WaveMode::Extraordinary, k, extraordinaryField(m, k, s), propagating, rayNormal, q};
}

// The time-averaged Poynting flux along N of a propagating wave of wave vector k, unit field e and ray normal
// component rayNormal, up to the factor common to every wave: N . Re(E x conj(H)) with H = k x E, i.e.
// |k - E (k.E)| times the normal component of the ray.
double normalFlux(const Vec3& k, const Vec3& e, double rayNormal) {
    return length(k - e * dot(k, e)) * rayNormal;
}

// The propagating wave w as a PlaneWave, its unit field e given.
PlaneWave toPlaneWave(const UniaxialMedium* crystal, const Wave& w, const Vec3& e) {
    const Vec3 k = realPart(w.k);
    PlaneWave p;
    p.mode = w.mode;
    p.index = length(k);
    p.waveNormal = k / p.index;
    p.field = e;
    p.ray = w.mode == WaveMode::Extraordinary ? normalize(epsilonTimes(*crystal, k)) : p.waveNormal;
    return p;
}
PlaneWave toPlaneWave(const UniaxialMedium* crystal, const Wave& w) {
    return toPlaneWave(crystal, w, normalize(realPart(w.field)));
}

// The four tangential components (E.t1, E.t2, H.t1, H.t2) of a wave, t1 = s, t2 = N x s.
void tangential(const Wave& w, const Vec3& t1, const Vec3& t2, Complex out[4]) {
    const CVec3 h = cross(w.k, w.field);
    const CVec3 a = toComplex(t1), b = toComplex(t2);
    out[0] = dot(w.field, a);
    out[1] = dot(w.field, b);
    out[2] = dot(h, a);
    out[3] = dot(h, b);
}

// z / w without the library's scaled complex division (__divdc3): |w| is far from overflow here.
Complex divide(Complex z, Complex w) {
    return z * std::conj(w) / std::norm(w);
}

// Matches tangential E and H across the interface for `count` incident waves: incident + reflected =
// transmitted, the unknowns being the two reflected and the two transmitted amplitudes (n the isotropic
// medium's index). Fills the outgoing waves' amplitudes, flux ratios and shares.
//
// The isotropic medium's s and p waves need no general 4x4 solve: with q = N.k their tangential components
// are s: (1, 0, 0, q) and p: (0, q / n, -n, 0) (E = k x s / n, H = k x E = -n s as k.k = n^2), so s appears
// only in rows 0 and 3 and p only in rows 1 and 2. Eliminating them leaves a 2x2 system for the crystal's
// two waves (Yariv & Yeh ch. 4; Lekner 1991 reduces it the same way), solved by Cramer's rule.
void matchFields(const UniaxialMedium& crystal, bool crystalReflects, const Wave incident[2], int count,
                 const Wave reflected[2], const Wave transmitted[2], const Vec3& N, const Vec3& s, double n,
                 InterfaceWaves& out) {
    const Vec3 t2 = cross(N, s);
    // incident = sum of u_j A_j: A_j = +transmitted_j, -reflected_j; iso[0], iso[1] are the s and p waves.
    const Wave* crystalWaves = crystalReflects ? reflected : transmitted;
    const Wave* iso = crystalReflects ? transmitted : reflected;
    const double crystalSign = crystalReflects ? -1 : 1, isoSign = -crystalSign;
    Complex c[2][4];  // the crystal waves' columns A
    for (int j = 0; j < 2; ++j) {
        tangential(crystalWaves[j], s, t2, c[j]);
        for (Complex& v : c[j]) v *= crystalSign;
    }
    const Complex q = iso[0].q, g = q / (n * n);
    const Complex m00 = c[0][3] - q * c[0][0], m01 = c[1][3] - q * c[1][0];
    const Complex m10 = c[0][1] + g * c[0][2], m11 = c[1][1] + g * c[1][2];
    const Complex det = m00 * m11 - m01 * m10;
    if (!(std::norm(det) > 0)) throw Error("birefringence: the interface equations are singular");

    // x[row][i]: the amplitude of wave `row` (reflected 0, 1, transmitted 0, 1) for incident wave i.
    Complex x[4][2];
    const int crystalRow = crystalReflects ? 0 : 2, isoRow = 2 - crystalRow;
    for (int i = 0; i < count; ++i) {
        Complex b[4];
        tangential(incident[i], s, t2, b);
        const Complex r0 = b[3] - q * b[0], r1 = b[1] + g * b[2];
        const Complex u0 = divide(r0 * m11 - m01 * r1, det), u1 = divide(m00 * r1 - m10 * r0, det);
        x[crystalRow][i] = u0;
        x[crystalRow + 1][i] = u1;
        x[isoRow][i] = isoSign * (b[0] - c[0][0] * u0 - c[1][0] * u1);
        x[isoRow + 1][i] = isoSign * (c[0][2] * u0 + c[1][2] * u1 - b[2]) / n;
    }

    // Every incident basis wave has a unit real field and the same wave vector, so one incident flux serves.
    const double incidentFlux =
        normalFlux(realPart(incident[0].k), normalize(realPart(incident[0].field)), incident[0].rayNormal);
    const UniaxialMedium* reflectedIn = crystalReflects ? &crystal : nullptr;
    const UniaxialMedium* transmittedIn = crystalReflects ? nullptr : &crystal;
    auto fill = [&](OutgoingWave& o, const Wave& w, const UniaxialMedium* medium, int row, double sign) {
        o.propagating = w.propagating;
        double fieldScale;
        if (w.propagating) {
            const Vec3 field = realPart(w.field);
            fieldScale = length(field);
            o.wave = toPlaneWave(medium, w, field / fieldScale);
            o.fluxRatio = sign * normalFlux(realPart(w.k), o.wave.field, w.rayNormal) / incidentFlux;
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
        fill(out.reflected[j], reflected[j], reflectedIn, j, -1);
        fill(out.transmitted[j], transmitted[j], transmittedIn, 2 + j, 1);
    }
}

// s: perpendicular to the plane of incidence, normalize(kt x N); any perpendicular to N at normal incidence.
Vec3 sDirection(const Vec3& kt, const Vec3& N) {
    const Vec3 s = cross(kt, N);
    const double len = length(s);
    return len > 1e-12 ? s / len : perpendicularTo(N);
}

void checkMedia(const UniaxialMedium& crystal, double nOutside) {
    if (!(crystal.nO > 0 && crystal.nE > 0 && nOutside > 0))
        throw Error("birefringence: indices must be positive");
    if (!(std::fabs(dot(crystal.axis, crystal.axis) - 1) < 1e-9))
        throw Error("birefringence: the optic axis must be a unit vector");
}

}  // namespace

double extraordinaryIndex(const UniaxialMedium& medium, const Vec3& waveNormal) {
    const double c = dot(medium.axis, waveNormal);
    const double s2 = std::fmax(0.0, 1 - c * c);
    return 1 / std::sqrt(c * c / (medium.nO * medium.nO) + s2 / (medium.nE * medium.nE));
}

PlaneWave ordinaryWave(const UniaxialMedium& medium, const Vec3& waveNormal) {
    const Wave w{WaveMode::Ordinary,
                 toComplex(waveNormal * medium.nO),
                 ordinaryField(medium, toComplex(waveNormal), perpendicularTo(medium.axis)),
                 true,
                 0,
                 0};
    return toPlaneWave(&medium, w);
}

PlaneWave extraordinaryWave(const UniaxialMedium& medium, const Vec3& waveNormal) {
    const Vec3 k = waveNormal * extraordinaryIndex(medium, waveNormal);
    const Wave w{WaveMode::Extraordinary,
                 toComplex(k),
                 extraordinaryField(medium, toComplex(k), perpendicularTo(medium.axis)),
                 true,
                 0,
                 0};
    return toPlaneWave(&medium, w);
}

InterfaceWaves enterCrystal(const UniaxialMedium& crystal, const Vec3& direction, const Vec3& outwardNormal,
                            double nOutside) {
    checkMedia(crystal, nOutside);
    const Vec3 N = -outwardNormal;  // along the incident energy flow, into the crystal
    const double cosI = dot(direction, N);
    if (!(cosI > 0)) throw Error("birefringence: the light does not travel into the facet");
    const Vec3 kt = (direction - N * cosI) * nOutside;
    const Vec3 s = sDirection(kt, N);

    const Wave incident[2] = {isotropicWave(WaveMode::S, nOutside, kt, N, s, 1),
                              isotropicWave(WaveMode::P, nOutside, kt, N, s, 1)};
    const Wave reflected[2] = {isotropicWave(WaveMode::S, nOutside, kt, N, s, -1),
                               isotropicWave(WaveMode::P, nOutside, kt, N, s, -1)};
    const Wave transmitted[2] = {
        ordinaryInterfaceWave(crystal, kt, N, s, 1),
        extraordinaryInterfaceWave(crystal, extraordinaryRoots(crystal, kt, N), kt, N, s, 1)};
    InterfaceWaves out;
    out.incidentCount = 2;
    for (int i = 0; i < 2; ++i) out.incident[i] = toPlaneWave(nullptr, incident[i]);
    matchFields(crystal, false, incident, 2, reflected, transmitted, N, s, nOutside, out);
    return out;
}

InterfaceWaves leaveCrystal(const UniaxialMedium& crystal, const PlaneWave& incident,
                            const Vec3& outwardNormal, double nOutside) {
    checkMedia(crystal, nOutside);
    const Vec3& N = outwardNormal;  // along the incident energy flow, out of the crystal
    if (incident.mode != WaveMode::Ordinary && incident.mode != WaveMode::Extraordinary)
        throw Error("birefringence: a wave inside the crystal is ordinary or extraordinary");
    if (!(dot(incident.ray, N) > 0))
        throw Error("birefringence: the wave's energy does not travel into the facet");
    const Vec3 k = incident.waveNormal * incident.index;
    const Vec3 kt = k - N * dot(k, N);
    const Vec3 s = sDirection(kt, N);

    // The incident wave as given (its field may be any one of a degenerate pair), its ray's normal
    // component from the same root as its reflected twin's (Wave), unless rounding at grazing loses the root;
    // an ordinary twin's is the reflected ordinary wave's negated.
    const ExtraordinaryRoots roots = extraordinaryRoots(crystal, kt, N);
    const Wave reflected[2] = {ordinaryInterfaceWave(crystal, kt, N, s, -1),
                               extraordinaryInterfaceWave(crystal, roots, kt, N, s, -1)};
    const double twinRayNormal = incident.mode == WaveMode::Ordinary ? -reflected[0].rayNormal
                                 : roots.discriminant > 0
                                     ? extraordinaryRayNormal(roots, 1, extraordinaryRoot(roots, 1).real())
                                     : 0;
    const double rayNormal = twinRayNormal > 0 ? twinRayNormal : dot(incident.ray, N);
    const Wave in[1] = {{incident.mode, toComplex(k), toComplex(incident.field), true, rayNormal, dot(k, N)}};
    const Wave transmitted[2] = {isotropicWave(WaveMode::S, nOutside, kt, N, s, 1),
                                 isotropicWave(WaveMode::P, nOutside, kt, N, s, 1)};
    InterfaceWaves out;
    out.incidentCount = 1;
    out.incident[0] = incident;
    matchFields(crystal, true, in, 1, reflected, transmitted, N, s, nOutside, out);
    return out;
}

double shareOf(const OutgoingWave& wave, const Coherency& j) {
    const Complex ts = wave.amplitude[0], tp = wave.amplitude[1];
    return wave.fluxRatio *
           (std::norm(ts) * j.ss + std::norm(tp) * j.pp + 2 * (ts * std::conj(tp) * j.sp).real());
}

}  // namespace facetlight
