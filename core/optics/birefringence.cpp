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
};

// The normal component q of the wave vector kt + q N of each outgoing wave. `side` is +1 for the waves whose
// energy leaves along +N (transmitted), -1 for those leaving along -N (reflected); an evanescent wave must
// decay on its side, Im(q) side > 0. For |k|^2 = n^2: q = side sqrt(n^2 - kt^2), the flux is along k. For the
// extraordinary wave, k.eps.k = n_o^2 n_e^2 is the quadratic a q^2 + 2 b q + c = 0 with a = N.eps.N,
// b = kt.eps.N, c = kt.eps.kt - n_o^2 n_e^2; its ray is along eps k (the normal to the index surface), whose
// normal component is b + a q = +-sqrt(b^2 - a c): the root with +sqrt sends energy along +N whichever way
// its wave normal points. The principal complex square root gives the decaying root for either side.
Wave isotropicWave(WaveMode mode, double n, const Vec3& kt, const Vec3& N, const Vec3& s, int side) {
    const Complex q = double(side) * std::sqrt(Complex(n * n - dot(kt, kt)));
    const CVec3 k = toComplex(kt) + toComplex(N) * q;
    const bool propagating = n * n - dot(kt, kt) > 0;
    const CVec3 field = mode == WaveMode::S ? toComplex(s) : cross(k, toComplex(s)) * (1 / n);
    return {mode, k, field, propagating, propagating ? q.real() / n : 0};
}

Wave ordinaryInterfaceWave(const UniaxialMedium& m, const Vec3& kt, const Vec3& N, const Vec3& s, int side) {
    const double q2 = m.nO * m.nO - dot(kt, kt);
    const Complex q = double(side) * std::sqrt(Complex(q2));
    const CVec3 k = toComplex(kt) + toComplex(N) * q;
    return {WaveMode::Ordinary, k, ordinaryField(m, k, s), q2 > 0, q2 > 0 ? q.real() / m.nO : 0};
}

Wave extraordinaryInterfaceWave(const UniaxialMedium& m, const Vec3& kt, const Vec3& N, const Vec3& s,
                                int side) {
    const Vec3 epsN = epsilonTimes(m, N);
    const double a = dot(N, epsN), b = dot(kt, epsN);
    const double c = dot(kt, epsilonTimes(m, kt)) - m.nO * m.nO * m.nE * m.nE;
    const double discriminant = b * b - a * c;
    const Complex q = (-b + double(side) * std::sqrt(Complex(discriminant))) / a;
    const CVec3 k = toComplex(kt) + toComplex(N) * q;
    const bool propagating = discriminant > 0;
    const double rayNormal =
        propagating ? side * std::sqrt(discriminant) / length(epsilonTimes(m, realPart(k))) : 0;
    return {WaveMode::Extraordinary, k, extraordinaryField(m, k, s), propagating, rayNormal};
}

// The time-averaged Poynting flux along N of a propagating wave of unit field, up to the factor common to
// every wave: N . Re(E x conj(H)) with H = k x E, i.e. |k - E (k.E)| times the normal component of the ray.
double normalFlux(const Wave& w) {
    const Vec3 k = realPart(w.k), e = normalize(realPart(w.field));
    return length(k - e * dot(k, e)) * w.rayNormal;
}

PlaneWave toPlaneWave(const UniaxialMedium* crystal, const Wave& w) {
    const Vec3 k = realPart(w.k);
    PlaneWave p;
    p.mode = w.mode;
    p.index = length(k);
    p.waveNormal = k / p.index;
    p.field = normalize(realPart(w.field));
    p.ray = w.mode == WaveMode::Extraordinary ? normalize(epsilonTimes(*crystal, k)) : p.waveNormal;
    return p;
}

// Solves A x = b for a 4x4 complex A and `columns` right-hand sides by Gaussian elimination with partial
// pivoting; b is overwritten with x.
void solve4(Complex a[4][4], Complex b[4][2], int columns) {
    for (int col = 0; col < 4; ++col) {
        int pivot = col;
        for (int r = col + 1; r < 4; ++r)
            if (std::abs(a[r][col]) > std::abs(a[pivot][col])) pivot = r;
        if (!(std::abs(a[pivot][col]) > 0))
            throw Error("birefringence: the interface equations are singular");
        if (pivot != col) {
            for (int j = 0; j < 4; ++j) std::swap(a[col][j], a[pivot][j]);
            for (int j = 0; j < columns; ++j) std::swap(b[col][j], b[pivot][j]);
        }
        for (int r = col + 1; r < 4; ++r) {
            const Complex f = a[r][col] / a[col][col];
            for (int j = col; j < 4; ++j) a[r][j] -= f * a[col][j];
            for (int j = 0; j < columns; ++j) b[r][j] -= f * b[col][j];
        }
    }
    for (int col = 3; col >= 0; --col)
        for (int j = 0; j < columns; ++j) {
            Complex sum = b[col][j];
            for (int k = col + 1; k < 4; ++k) sum -= a[col][k] * b[k][j];
            b[col][j] = sum / a[col][col];
        }
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

// Matches tangential E and H across the interface for `count` incident waves: incident + reflected =
// transmitted, the unknowns being the two reflected and the two transmitted amplitudes. Fills the outgoing
// waves' amplitudes, flux ratios and shares.
void matchFields(const UniaxialMedium& crystal, bool crystalReflects, const Wave incident[2], int count,
                 const Wave reflected[2], const Wave transmitted[2], const Vec3& N, const Vec3& s,
                 InterfaceWaves& out) {
    const Vec3 t2 = cross(N, s);
    Complex a[4][4], b[4][2], column[4];
    for (int j = 0; j < 2; ++j) {
        tangential(reflected[j], s, t2, column);
        for (int r = 0; r < 4; ++r) a[r][j] = -column[r];
        tangential(transmitted[j], s, t2, column);
        for (int r = 0; r < 4; ++r) a[r][2 + j] = column[r];
    }
    for (int i = 0; i < count; ++i) {
        tangential(incident[i], s, t2, column);
        for (int r = 0; r < 4; ++r) b[r][i] = column[r];
    }
    solve4(a, b, count);

    // Every incident basis wave has a unit real field and the same wave vector, so one incident flux serves.
    const double incidentFlux = normalFlux(incident[0]);
    const UniaxialMedium* reflectedIn = crystalReflects ? &crystal : nullptr;
    const UniaxialMedium* transmittedIn = crystalReflects ? nullptr : &crystal;
    auto fill = [&](OutgoingWave& o, const Wave& w, const UniaxialMedium* medium, int row, double sign) {
        o.propagating = w.propagating;
        double fieldScale = std::sqrt(norm2(w.field));
        if (w.propagating) {
            o.wave = toPlaneWave(medium, w);
            fieldScale = length(realPart(w.field));
            o.fluxRatio = sign * normalFlux(w) / incidentFlux;
        }
        for (int i = 0; i < count; ++i) {
            // The amplitude refers to the unit field (wave.field), not to the unnormalised one solved for.
            o.amplitude[i] = b[row][i] * fieldScale;
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
    const Wave w{WaveMode::Ordinary, toComplex(waveNormal * medium.nO),
                 ordinaryField(medium, toComplex(waveNormal), perpendicularTo(medium.axis)), true, 0};
    return toPlaneWave(&medium, w);
}

PlaneWave extraordinaryWave(const UniaxialMedium& medium, const Vec3& waveNormal) {
    const Vec3 k = waveNormal * extraordinaryIndex(medium, waveNormal);
    const Wave w{WaveMode::Extraordinary, toComplex(k),
                 extraordinaryField(medium, toComplex(k), perpendicularTo(medium.axis)), true, 0};
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
    const Wave transmitted[2] = {ordinaryInterfaceWave(crystal, kt, N, s, 1),
                                 extraordinaryInterfaceWave(crystal, kt, N, s, 1)};
    InterfaceWaves out;
    out.incidentCount = 2;
    for (int i = 0; i < 2; ++i) out.incident[i] = toPlaneWave(nullptr, incident[i]);
    matchFields(crystal, false, incident, 2, reflected, transmitted, N, s, out);
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
    // component from the same root as its reflected twin's (Wave), unless rounding at grazing loses the root.
    const Wave twin = incident.mode == WaveMode::Ordinary ? ordinaryInterfaceWave(crystal, kt, N, s, 1)
                                                          : extraordinaryInterfaceWave(crystal, kt, N, s, 1);
    const double rayNormal = twin.rayNormal > 0 ? twin.rayNormal : dot(incident.ray, N);
    const Wave in[1] = {{incident.mode, toComplex(k), toComplex(incident.field), true, rayNormal}};
    const Wave reflected[2] = {ordinaryInterfaceWave(crystal, kt, N, s, -1),
                               extraordinaryInterfaceWave(crystal, kt, N, s, -1)};
    const Wave transmitted[2] = {isotropicWave(WaveMode::S, nOutside, kt, N, s, 1),
                                 isotropicWave(WaveMode::P, nOutside, kt, N, s, 1)};
    InterfaceWaves out;
    out.incidentCount = 1;
    out.incident[0] = incident;
    matchFields(crystal, true, in, 1, reflected, transmitted, N, s, out);
    return out;
}

double shareOf(const OutgoingWave& wave, const Coherency& j) {
    const Complex ts = wave.amplitude[0], tp = wave.amplitude[1];
    return wave.fluxRatio *
           (std::norm(ts) * j.ss + std::norm(tp) * j.pp + 2 * (ts * std::conj(tp) * j.sp).real());
}

}  // namespace facetlight
