#pragma once
// The optics of one plane interface between a uniaxial crystal and an isotropic medium (air): the waves a
// plane wave makes there, their directions, polarisations, complex amplitudes and energy shares
// (docs/optics.md, "Birefringence: waves at an interface").
//
// Model: a non-magnetic crystal of dielectric tensor eps = n_o^2 I + (n_e^2 - n_o^2) c c^T (unit optic axis
// c). Wave vectors are in units of the vacuum wave number, so |k| is the index along the wave normal. At the
// interface the tangential part of k is conserved; each outgoing wave's normal component q solves its
// dispersion relation (|k| = n_o for the ordinary wave, k.eps.k = n_o^2 n_e^2 for the extraordinary one) and
// is chosen by the side its energy flows to, not by its wave normal; the four amplitudes (two reflected, two
// transmitted) follow from the continuity of tangential E and H = k x E (mu = 1), in complex arithmetic so
// that total internal reflection (evanescent waves) needs no special case. Sources: Born & Wolf, Principles
// of Optics, ch. 15 (crystal optics); Yariv & Yeh, Optical Waves in Crystals, ch. 4; Weidlich & Wilkie,
// "Realistic rendering of birefringency in uniaxial crystals", ACM TOG 27(1), 2008; Lekner, "Reflection and
// refraction by uniaxial crystals", J. Phys.: Condens. Matter 3, 6121 (1991), whose amplitudes r_ss ... t_pe
// this solves numerically.
//
// Why a numerical solve rather than Lekner's closed forms: one code path serves both sides of the interface,
// any axis, and total internal reflection, and the isotropic limit (n_o == n_e) reduces to Fresnel's s/p
// amplitudes to rounding. The isotropic side's s and p waves are eliminated in closed form, which leaves a
// 2x2 complex system for the crystal's two waves. Everything is fixed-size: no heap allocation per call.
#include <array>
#include <complex>

#include "geometry/ray.h"
#include "optics/polarization.h"

namespace facetlight {

using Complex = std::complex<double>;

// A uniaxial crystal: ordinary and extraordinary indices and the unit optic axis. n_o == n_e is an isotropic
// medium (then the "ordinary" and "extraordinary" waves are just two orthogonal polarisations). The interface
// functions refuse (Error) an index that is not positive or an axis that is not of unit length.
struct UniaxialMedium {
    double nO = 1;
    double nE = 1;
    Vec3 axis{0, 0, 1};
};

// The extraordinary index along a unit wave normal at angle theta to the axis:
// 1 / n^2 = cos^2 theta / n_o^2 + sin^2 theta / n_e^2 (Born & Wolf ch. 15).
double extraordinaryIndex(const UniaxialMedium& medium, const Vec3& waveNormal);

// A biaxial crystal (docs/optics.md, "Biaxial crystals"): principal indices alpha <= beta <= gamma along the
// orthonormal principal axes x, y, z (the stone's frame), eps = alpha^2 x x^T + beta^2 y y^T + gamma^2 z z^T.
// alpha == beta or beta == gamma is a uniaxial crystal, and its waves are the uniaxial ones to rounding.
struct BiaxialMedium {
    double alpha = 1, beta = 1, gamma = 1;
    Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
};

// The two indices along a unit wave normal s, the smaller first: the roots n^2 of Fresnel's equation of wave
// normals, (s.eps.s) n^4 - s.(tr(eps) eps - eps^2).s n^2 + det eps = 0 (Born & Wolf, Principles of Optics,
// 7th ed., sec. 15.2.3, eq. 15.2.(24) multiplied out; Yariv & Yeh, Optical Waves in Crystals, sec. 4.3).
std::array<double, 2> waveIndices(const BiaxialMedium& medium, const Vec3& waveNormal);

// The two optic axes (binormals: wave normals along which both indices are beta), in the x-z plane at Vz
// from z on either side, tan Vz = (gamma / alpha) sqrt((beta^2 - alpha^2) / (gamma^2 - beta^2)) (Born & Wolf
// sec. 15.3.3); the +x one first.
std::array<Vec3, 2> opticAxes(const BiaxialMedium& medium);

// Ordinary and extraordinary in a uniaxial crystal, Fast (the smaller index) and Slow in a biaxial one; s (E
// perpendicular to the plane of incidence) and p (E in it) in the isotropic medium outside.
enum class WaveMode : unsigned char { S, P, Ordinary, Extraordinary, Fast, Slow };

// A propagating plane wave. All vectors are unit and real.
struct PlaneWave {
    WaveMode mode = WaveMode::S;
    Vec3 waveNormal;   // k / |k|
    Vec3 ray;          // energy (Poynting) direction; differs from waveNormal only for an extraordinary wave
    Vec3 field;        // E; for ordinary waves perpendicular to the axis and to k
    double index = 1;  // |k|: n_o, n(theta) or the outside index
};

// The crystal's eigenmodes along a unit wave normal. Along the axis (where the two are degenerate) the
// ordinary E is taken perpendicular to the axis in a fixed but arbitrary direction, and the extraordinary
// E = k x E_o.
PlaneWave ordinaryWave(const UniaxialMedium& medium, const Vec3& waveNormal);
PlaneWave extraordinaryWave(const UniaxialMedium& medium, const Vec3& waveNormal);
// A biaxial crystal's Fast or Slow eigenmode along a unit wave normal; its E is the null vector of the wave
// matrix k k^T - |k|^2 I + eps, its ray along k - E (E.k) (the Poynting vector E x (k x E) of a unit E).
// Along an optic axis, where the two are degenerate, E is one of a fixed but arbitrary orthogonal pair.
PlaneWave biaxialWave(const BiaxialMedium& medium, const Vec3& waveNormal, WaveMode mode);

// One outgoing wave of an interface. Amplitudes are relative to the incident wave of unit E (per incident
// basis polarisation: from outside s then p, from inside only [0]); the wave's field is wave.field times the
// amplitude, with fields going as exp(i (k.r - omega t)) (so total internal reflection gives Fresnel's phases
// as -delta_s, -delta_p). fluxRatio is the wave's flux through the interface per unit |amplitude|^2, relative
// to the incident wave's, so share[i] = fluxRatio * |amplitude[i]|^2 is its share of the incident energy. An
// evanescent wave (propagating == false: beyond total internal reflection) carries no energy; its `wave` is
// not set.
struct OutgoingWave {
    PlaneWave wave;
    bool propagating = false;
    Complex amplitude[2] = {};
    double fluxRatio = 0;
    double share[2] = {};
};

// An incident state that is partially polarised: the coherency matrix J = <a a^H> of its amplitudes
// a = (a_s, a_p) over the incident basis (from outside; from inside only ss is used). Unit intensity when
// ss + pp == 1; unpolarised light is {0.5, 0.5, 0}.
struct Coherency {
    double ss = 0.5;
    double pp = 0.5;
    Complex sp{0, 0};  // <a_s conj(a_p)>
};

// The waves of one interface. From outside: incident[0], [1] are the s and p waves, reflected[] the s and p
// waves outside, transmitted[] the ordinary and extraordinary waves inside (a biaxial crystal's Fast and Slow
// ones). From inside: incident[0] is the crystal wave, reflected[] the crystal's two waves inside,
// transmitted[] the s and p waves outside. s = normalize(k_incident x N) with N the normal along the incident
// energy flow (a fixed direction perpendicular to N at normal incidence); each outside wave's p field is k /
// |k| x s.
struct InterfaceWaves {
    int incidentCount = 0;
    PlaneWave incident[2];
    OutgoingWave reflected[2];
    OutgoingWave transmitted[2];

    // No transmitted wave propagates: the reflected shares sum to 1.
    bool totalInternalReflection() const {
        return !transmitted[0].propagating && !transmitted[1].propagating;
    }
};

// Light from the isotropic medium of index nOutside, travelling along unit `direction`, meets a crystal facet
// of unit outward normal `outwardNormal` (dot(direction, outwardNormal) < 0, else Error).
InterfaceWaves enterCrystal(const UniaxialMedium& crystal, const Vec3& direction, const Vec3& outwardNormal,
                            double nOutside = 1);

// A crystal eigenmode (from ordinaryWave, extraordinaryWave or an earlier interface) meets a facet of unit
// outward normal `outwardNormal` from inside (dot(incident.ray, outwardNormal) > 0, else Error; its wave
// normal may point either way for an extraordinary wave).
InterfaceWaves leaveCrystal(const UniaxialMedium& crystal, const PlaneWave& incident,
                            const Vec3& outwardNormal, double nOutside = 1);

// The same for a biaxial crystal (docs/optics.md, "Biaxial crystals"). Each crystal wave's normal component q
// is a root of the quartic det(k k^T - |k|^2 I + eps) = 0 in q (Fresnel's equation of wave normals with
// k = kt + q N, the Booker quartic of stratified-media optics); of its four roots the two whose energy flows
// away from the facet on the crystal's side (Im q > 0 that way when evanescent) are the crystal's waves,
// Fast (the smaller index, or evanescent first) before Slow. Amplitudes and shares as for a uniaxial crystal.
InterfaceWaves enterCrystal(const BiaxialMedium& crystal, const Vec3& direction, const Vec3& outwardNormal,
                            double nOutside = 1);
InterfaceWaves leaveCrystal(const BiaxialMedium& crystal, const PlaneWave& incident,
                            const Vec3& outwardNormal, double nOutside = 1);

// The energy share of a wave of flux ratio fluxRatio and amplitudes (ts, tp) for an incident state of
// coherency J over the incident basis: fluxRatio * sum_mn t_m J_mn conj(t_n).
double shareOf(double fluxRatio, Complex ts, Complex tp, const Coherency& incident);
inline double shareOf(const OutgoingWave& wave, const Coherency& incident) {
    return shareOf(wave.fluxRatio, wave.amplitude[0], wave.amplitude[1], incident);
}

// shareOf() part by part over the number type T (double, or the packet walk's lanes of doubles): amplitudes
// ts and tp, coherency J = {ss, pp, sp}; std::norm and std::complex's textbook products written out.
template <class T>
[[gnu::always_inline]] inline T shareOfParts(T fluxRatio, T tsRe, T tsIm, T tpRe, T tpIm, T ss, T pp, T spRe,
                                             T spIm) {
    const T cRe = tsRe * tpRe - tsIm * -tpIm, cIm = tsRe * -tpIm + tsIm * tpRe;  // ts conj(tp)
    return fluxRatio * ((tsRe * tsRe + tsIm * tsIm) * ss + (tpRe * tpRe + tpIm * tpIm) * pp +
                        T(2.0) * (cRe * spRe - cIm * spIm));
}

// A photon's state (optics/polarization.h) along d as the coherency matrix over the basis whose s is `s`
// (across d, p = d x s): J_ss = (S0 + S1) / 2, J_pp = (S0 - S1) / 2, J_sp = (S2 - i S3) / 2, S0 = 1. Over
// the number types: the state st already referred to s (F: float or lanes of floats), each sum widened to T
// by widen().
template <class T>
struct CoherencyParts {
    T ss, pp, spRe, spIm;
};
template <class T, class F, class Widen>
[[gnu::always_inline]] inline CoherencyParts<T> coherencyParts(const StokesOf<F>& st, Widen&& widen) {
    return {T(0.5) * widen(st.s0 + st.s1), T(0.5) * widen(st.s0 - st.s1), T(0.5) * widen(st.s2),
            T(-0.5) * widen(st.s3)};
}
inline Coherency coherencyOf(const Polarization& pol, const Vec3f& d, const Vec3f& s) {
    const CoherencyParts<double> j =
        coherencyParts<double>(rotateFrame(pol.stokes, pol.x, s, d), [](float x) { return double(x); });
    return {j.ss, j.pp, Complex(j.spRe, j.spIm)};
}
// The Stokes vector (S0 = 1) of the light of amplitudes a_s and a_p over an s-p basis (the inverse of the
// above): S1 = |a_s|^2 - |a_p|^2, S2 = 2 Re(a_s conj(a_p)), S3 = -2 Im(a_s conj(a_p)), over |a_s|^2 + |a_p|^2.
inline Stokes stokesOf(Complex as, Complex ap) {
    const double s0 = std::norm(as) + std::norm(ap);
    const Complex c = as * std::conj(ap);
    return {1, float((std::norm(as) - std::norm(ap)) / s0), float(2 * c.real() / s0), float(-2 * c.imag() / s0)};
}

}  // namespace facetlight
