#pragma once
// The walk of photons through a stone, shared by the per-photon path, the packet walk of photon_packet.cpp
// and the view rays of the ASET view (render/aset.cpp). It reads the world from the scene and the trace's
// own settings and caches from the TraceBase.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

#include "intersect/convex_intersector.h"
#include "intersect/embree_intersector.h"
#include "optics/absorption.h"
#include "optics/birefringence.h"
#include "optics/fresnel.h"
#include "optics/uniaxial_interface.h"
#include "trace/fire_trace.h"
#include "trace/photon_tracer.h"
#include "trace/trace_base.h"
#include "util/random.h"

namespace facetlight {

// The walk of one photon, written once and specialised by intersector (no virtual call per ray) and by what
// is recorded (a tally for statistics, a path for the renderer).
class PhotonWalker {
  public:
    struct Tally;
    struct TallyWithExits;

    // A photon inside the stone, between two interactions.
    struct Photon {
        Rng rng{0, 0};
        Vec3f p, d;
        float n = 0;
        uint32_t bounces = 0;
        Polarization pol;  // when the trace is polarised
        float nE = 0;  // a birefringent stone's extraordinary index (n is the ordinary one); biaxial: gamma
        float nA = 0;  // a biaxial stone's alpha (n is its beta)
        PlaneWave wave;    // inside a birefringent stone: the ordinary or extraordinary wave it travels as
        bool coherent = false;  // near the optic axis instead: both waves in phase, one state at n_o (pol)
        // Absorption per mesh unit (TraceBase::absorption): the photon's, or its ordinary wave's, and its
        // extraordinary wave's in a birefringent trace; and the optical depth it has left, drawn at entry.
        float absorption = 0, absorptionE = 0, depth = 0;
        float absorptionRay[3] = {};  // a trichroic trace's X, Y and Z rays' (TraceBase::rayAbsorption)

        // Index n (n_o in a birefringent stone) for a ray that carries one index: n_e is n plus the
        // birefringence at 589.3 nm, its own dispersion left out (docs/optics.md, "Birefringent stones").
        void setIndex(const TraceBase& s, float index) {
            n = index;
            nE = index + s.birefringenceD();
            nA = index + s.alphaOffsetD();
        }
        void setAbsorption(const TraceBase& s, float wavelengthNm) {
            absorption = s.absorption(wavelengthNm);
            absorptionE = s.birefringent() ? s.extraordinaryAbsorption(wavelengthNm) : 0.0f;
            if (s.trichroic())
                for (int axis = 0; axis < 3; ++axis)
                    absorptionRay[axis] = s.rayAbsorption(axis, wavelengthNm);
        }
    };

    // Beer-Lambert by the free path (docs/optics.md, "Absorption"): a photon that enters an absorbing stone
    // draws once the optical depth it will cross, -ln(1 - u), exponentially distributed; each segment of
    // length L uses up alpha L of it (depthLeft), and the photon is absorbed on the segment where it runs
    // out. The chance to cross a segment is then exp(-alpha L) whatever came before, as Beer-Lambert says,
    // with one draw and one logarithm per photon rather than per segment, and only add, sub and mul per
    // segment (the same bits in every walk and SIMD target).
    static float freePath(Rng& rng) { return float(-std::log1p(-rng.uniformDouble())); }
    // Whether a photon with these coefficients draws a free path: not in a clear stone, nor at a wavelength
    // the stone does not absorb.
    static bool absorbing(const Photon& ph) { return ph.absorption > 0 || ph.absorptionE > 0; }

    // Photon `ph` at the index and wavelength of one band of the fire trace.
    static void setBand(const TraceBase& s, const FireBand& band, Photon& ph) {
        ph.setIndex(s, band.index);
        ph.setAbsorption(s, band.wavelengthNm);
    }

    // Draws photon `index` and takes it to the stone; true when it is inside and has to be stepped on.
    template <class Intersector, class Visitor>
    static bool start(const TraceBase& s, const Intersector& isect, uint64_t index, Visitor& visit,
                      Photon& ph) {
        ph.rng = Rng(s.settings().seed, index);
        ph.bounces = 0;
        const LightRay ray = s.scene().light().sample(ph.rng);
        float wavelength = float(Material::kSodiumD);
        ph.n = s.scene().fixedIndex();
        if (s.scene().dispersive()) {
            wavelength = 380.0f + 400.0f * ph.rng.uniform();
            ph.n = float(s.scene().material().index(wavelength));
        }
        visit.wavelength(wavelength);
        if (s.birefringent()) ph.nE = s.principalIndex(2, wavelength);
        if (s.biaxial()) ph.nA = s.principalIndex(0, wavelength);
        ph.setAbsorption(s, wavelength);
        return enter(s, isect, ray, visit, ph);
    }

    // Takes a photon drawn from the light to the stone, with ph.rng and ph.n set; true when it is inside.
    // The fire trace (trace/fire_trace.cpp) enters one drawn ray at several indices of refraction.
    template <class Intersector, class Visitor>
    static bool enter(const TraceBase& s, const Intersector& isect, const LightRay& ray, Visitor& visit,
                      Photon& ph) {
        const Vec3f d(ray.direction), p(ray.origin);
        SurfaceHit hit;
        if (!(s.scene().beamEntry() ? s.scene().beamEntry()->enter(p, hit) : isect.enter(p, d, hit))) {
            visit.missed();
            return false;
        }
        return enterAt(s, hit.facet, p + d * hit.t, d, visit, ph);
    }

    // enter() once the entry search has found where the ray along d meets the stone: facet `facet` at p. The
    // packet walk of a birefringent stone calls it for each lane of a collimated beam after its packet's
    // entry search, with the crystal's waves there (`entry`, enterCrystal()'s) where its lanes found them.
    template <class Visitor>
    static bool enterAt(const TraceBase& s, uint32_t facet, const Vec3f& p, Vec3f d, Visitor& visit,
                        Photon& ph, const uniaxial::EntryLane* entry = nullptr) {
        if (!s.fixedEntries().empty()) {
            const TraceBase::FixedEntry& e = s.fixedEntries()[facet];
            if (ph.rng.uniform() < e.reflectance) {
                visit.reflectedAtEntry(facet, p, e.reflected);
                return false;
            }
            d = e.refracted;
        } else if (s.polarized()) {
            ph.pol = s.sourcePolarization(d);
            const Vec3f& normal = s.scene().normal(facet);
            if (!(s.birefringent() ? enterCrystalWave(s, normal, facet, p, d, visit, ph, entry)
                                   : enterPolarized(normal, 1.0f / ph.n, facet, p, d, visit, ph)))
                return false;
        } else {
            const Vec3f normal = s.scene().normal(facet);
            const float cosI = std::clamp(-dot(d, normal), 0.0f, 1.0f);
            const float eta = 1.0f / ph.n;
            const FresnelResult fr = fresnel(cosI, eta);
            if (ph.rng.uniform() < fr.reflectance) {
                visit.reflectedAtEntry(facet, p, reflectOff(d, normal, cosI));
                return false;
            }
            d = refractIn(d, normal, eta, cosI, fr.cosT);
        }
        ph.depth = absorbing(ph) ? freePath(ph.rng) : 0.0f;
        visit.entered(facet);
        ph.p = p;
        ph.d = d;
        return true;
    }

    // The photon's next interaction inside; true while it stays inside.
    template <class Intersector, class Visitor>
    static bool step(const TraceBase& s, const Intersector& isect, Visitor& visit, Photon& ph) {
        SurfaceHit hit;
        if (!isect.leave(ph.p, ph.d, hit)) {
            visit.lost(ph.bounces);
            return false;
        }
        return meet(s, hit, visit, ph);
    }

    // step() once the exit search has found `hit`: the segment's absorption, then the facet's reflection or
    // exit. The packet walk of a birefringent stone calls it for each lane after its packet's exit search,
    // with the crystal's waves there (`leaving`, leaveCrystal()'s) where its lanes found them.
    template <class Visitor>
    static bool meet(const TraceBase& s, const SurfaceHit& hit, Visitor& visit, Photon& ph,
                     const uniaxial::LeavingLane* leaving = nullptr) {
        if (s.absorbs()) {
            if constexpr (requires { visit.attenuated(0.0f); }) {
                // A weighted view ray (viewer/colour_view.cpp) keeps going and adds up alpha L instead.
                visit.attenuated(segmentAbsorption(s, ph) * hit.t);
            } else {
                ph.depth = depthLeft(ph.depth, segmentAbsorption(s, ph), hit.t);
                if (ph.depth < 0) {
                    visit.absorbed(ph.bounces);
                    return false;
                }
            }
        }
        if (s.birefringent() && !ph.coherent) return stepCrystalWave(s, hit, visit, ph, leaving);
        const Vec3f p = ph.p + ph.d * hit.t, d = ph.d;
        const Vec3f normal = s.scene().normal(hit.facet);
        const float cosI = std::clamp(dot(d, normal), 0.0f, 1.0f), n = ph.n;
        if (s.polarized()) {
            // The facet's s-p frame; the same draws as below, none under total internal reflection.
            const FacetMeeting<float> m = meetFacet(ph.pol, d, normal, cosI, n);
            const FacetWaves& w = m.waves;
            if (!w.totalInternal && ph.rng.uniform() >= w.reflected.share(m.stokes)) {
                const Vec3f out = refractOut(d, normal, n, cosI, w.cosT);
                // The state it leaves in, for a visitor that reads it (the photon goes no further).
                if constexpr (requires { visit.exitPolarization(ph.pol, out); }) {
                    ph.pol = {w.refracted.apply(m.stokes), toVec3f(m.s)};
                    visit.exitPolarization(ph.pol, out);
                }
                visit.exited(hit.facet, p, out, ph.bounces);
                return false;
            }
            ph.pol = {w.reflected.apply(m.stokes), toVec3f(m.s)};
        } else {
            const FresnelResult fr = fresnel(cosI, n);
            if (!fr.totalInternal && ph.rng.uniform() >= fr.reflectance) {
                visit.exited(hit.facet, p, refractOut(d, normal, n, cosI, fr.cosT), ph.bounces);
                return false;
            }
        }
        ph.p = p;
        ph.d = d - normal * (2 * cosI);
        if (ph.coherent) leaveAxisCone(s, ph);
        visit.internalReflection(hit.facet);
        if (++ph.bounces >= uint32_t(s.settings().maxBounces)) {
            visit.trapped(ph.bounces);
            return false;
        }
        return true;
    }

    // The coefficient along the photon's present segment: its own, or in a birefringent stone its wave's:
    // alpha_o for the ordinary wave (and near the axis, where both are ordinary-like), and for the
    // extraordinary wave alpha_o cos^2 theta + alpha_e sin^2 theta, theta between its wave normal and the
    // axis (docs/optics.md, "Absorption"; the walk-off between wave normal and ray, cos rho > 0.9999 for gem
    // birefringences, is left out). In a trichroic stone a wave of unit field e absorbs
    // alpha_X e_X^2 + alpha_Y e_Y^2 + alpha_Z e_Z^2 (a biaxial stone has no coherent zone).
    static float segmentAbsorption(const TraceBase& s, const Photon& ph) {
        if (s.trichroic()) {
            double alpha = 0;
            for (int axis = 0; axis < 3; ++axis) {
                const double c = dot(ph.wave.field, s.principalAxes()[size_t(axis)]);
                alpha += ph.absorptionRay[axis] * c * c;
            }
            return float(alpha);
        }
        if (!s.birefringent() || ph.coherent || ph.wave.mode != WaveMode::Extraordinary) return ph.absorption;
        const double c = dot(ph.wave.waveNormal, s.opticAxis());
        return float(extraordinaryAbsorption(ph.absorption, ph.absorptionE, c * c));
    }

    // A view ray: a photon's path run backwards (reciprocity), from `eye` along `dir` (stone frame) at index
    // n, drawing from ph.rng. At the first facet it reflects with the Fresnel probability
    // (visit.reflectedAtEntry, with the direction it leaves in) or refracts in (visit.entered) and is stepped
    // until it leaves (visit.exited), is trapped or is lost. False when it misses the stone. A reflection off a
    // non-convex stone is not followed back into it (as the tracer does).
    template <class Visitor>
    static bool view(const TraceBase& s, const Vec3f& eye, const Vec3f& dir, float n, Visitor& visit,
                     Photon& ph) {
        const Scene& scene = s.scene();
        SurfaceHit hit;
        if (!scene.enter(eye, dir, hit)) return false;
        const Vec3f p = eye + dir * hit.t;
        const Vec3f& normal = scene.normal(hit.facet);
        const float eta = 1.0f / n;
        ph.setIndex(s, n);
        if (s.polarized()) {
            // An unpolarised eye: by reciprocity the share it sees is what unpolarised light would bring it.
            ph.pol = {Stokes{}, frameAcross(dir, Vec3f(1, 0, 0))};
            Vec3f d = dir;
            if (!(s.birefringent() ? enterCrystalWave(s, normal, hit.facet, p, d, visit, ph)
                                   : enterPolarized(normal, eta, hit.facet, p, d, visit, ph)))
                return true;
            ph.d = d;
        } else {
            const float cosI = std::clamp(-dot(dir, normal), 0.0f, 1.0f);
            const FresnelResult fr = fresnel(cosI, eta);
            if (ph.rng.uniform() < fr.reflectance) {
                visit.reflectedAtEntry(hit.facet, p, reflectOff(dir, normal, cosI));
                return true;
            }
            ph.d = refractIn(dir, normal, eta, cosI, fr.cosT);
        }
        visit.entered(hit.facet);
        ph.p = p;
        ph.bounces = 0;
        while (step(s, scene, visit, ph)) {
        }
        return true;
    }

    // The polarised reflect-or-refract choice where a ray along d meets facet `facet` (outward normal
    // `normal`) at p from outside (eta = 1 / n): false after visit.reflectedAtEntry; else d is the refracted
    // direction and ph.pol the state inside.
    template <class Visitor>
    static bool enterPolarized(const Vec3f& normal, float eta, uint32_t facet, const Vec3f& p, Vec3f& d,
                               Visitor& visit, Photon& ph) {
        const float cosI = std::clamp(-dot(d, normal), 0.0f, 1.0f);
        const FacetMeeting<float> m = meetFacet(ph.pol, d, normal, cosI, eta);
        if (ph.rng.uniform() < m.waves.reflected.share(m.stokes)) {
            visit.reflectedAtEntry(facet, p, reflectOff(d, normal, cosI));
            return false;
        }
        d = refractIn(d, normal, eta, cosI, m.waves.cosT);
        ph.pol = {m.waves.refracted.apply(m.stokes), toVec3f(m.s)};
        return true;
    }

    // A birefringent stone (docs/optics.md, "Birefringent stones"): where a ray along d from outside meets
    // facet `facet` at p, it reflects or enters as the ordinary or the extraordinary wave (a biaxial stone's
    // fast or slow one), chosen by their energy shares for the photon's state (optics/birefringence.h); near
    // a uniaxial stone's optic axis it goes on as one polarised state at n_o instead
    // (TraceBase::nearOpticAxis). False after visit.reflectedAtEntry; else d is the wave's ray (energy)
    // direction and ph.wave the wave. `entry`, where given, is the interface's waves, already found.
    template <class Visitor>
    static bool enterCrystalWave(const TraceBase& s, const Vec3f& normal, uint32_t facet, const Vec3f& p,
                                 Vec3f& d, Visitor& visit, Photon& ph,
                                 const uniaxial::EntryLane* entry = nullptr) {
        if (!(dot(d, normal) < 0)) {  // grazing, where float rounding put the entry: all is reflected
            visit.reflectedAtEntry(facet, p, d);
            return false;
        }
        if (entry) return chooseCrystalWave(s, *entry, normal, facet, p, d, visit, ph);
        const InterfaceWaves w =
            s.biaxial() ? enterCrystal(s.biaxialCrystal(ph.nA, ph.n, ph.nE), toVec3(d), toVec3(normal))
                        : enterCrystal(s.crystal(ph.n, ph.nE), toVec3(d), toVec3(normal));
        return chooseCrystalWave(s, WavesEntry{w}, normal, facet, p, d, visit, ph);
    }
    // What chooseCrystalWave() reads of enterCrystal()'s waves (uniaxial::EntryLane: of the lanes'); wave w
    // is reflected s and p, then transmitted 0 and 1.
    struct WavesEntry {
        const InterfaceWaves& w;
        const OutgoingWave& wave(int i) const { return i < 2 ? w.reflected[i] : w.transmitted[i - 2]; }
        const Vec3& incidentS() const { return w.incident[0].field; }
        double fluxRatio(int i) const { return wave(i).fluxRatio; }
        Complex amplitude(int i, int k) const { return wave(i).amplitude[k]; }
        const PlaneWave& transmittedWave(int j) const { return w.transmitted[j].wave; }
        const Vec3& ordinaryNormal() const { return w.transmitted[0].wave.waveNormal; }
    };
    // The wave a photon's draw picks among an entry's (uniaxial::drawWave) for its state pol along d: -1
    // reflected, 0 or 1 the transmitted ordinary or extraordinary wave; or the lanes' draw where they made
    // it.
    template <class Waves>
    static int drawEntryWave(const Waves& w, const Polarization& pol, const Vec3f& d, Rng& rng) {
        const Coherency j = coherencyOf(pol, d, Vec3f(w.incidentS()));
        auto share = [&](int i) {
            const Complex ts = w.amplitude(i, 0), tp = w.amplitude(i, 1);
            return shareOfParts(w.fluxRatio(i), ts.real(), ts.imag(), tp.real(), tp.imag(), j.ss, j.pp,
                                j.sp.real(), j.sp.imag());
        };
        const uniaxial::WaveDraw<double> draw =
            uniaxial::drawWave<double>(rng.uniform(), share(0), share(1), share(2), share(3));
        return draw.pair ? -1 : draw.ordinary ? 0 : 1;
    }
    static int drawEntryWave(const uniaxial::EntryLane& w, const Polarization& pol, const Vec3f& d,
                             Rng& rng) {
        if (w.drawn == uniaxial::EntryLane::kNotDrawn)
            return drawEntryWave<uniaxial::EntryLane>(w, pol, d, rng);
        rng.skip();
        return w.drawn;
    }
    // enterCrystalWave() once the interface's waves w are known (WavesEntry or uniaxial::EntryLane).
    template <class Visitor, class Waves>
    static bool chooseCrystalWave(const TraceBase& s, const Waves& w, const Vec3f& normal, uint32_t facet,
                                  const Vec3f& p, Vec3f& d, Visitor& visit, Photon& ph) {
        ph.coherent = s.nearOpticAxis(w.ordinaryNormal());
        if (ph.coherent) return enterPolarized(normal, 1.0f / ph.n, facet, p, d, visit, ph);
        const int wave = drawEntryWave(w, ph.pol, d, ph.rng);
        if (wave < 0) {
            visit.reflectedAtEntry(facet, p, reflectOff(d, normal, std::clamp(-dot(d, normal), 0.0f, 1.0f)));
            return false;
        }
        ph.wave = w.transmittedWave(wave);
        d = Vec3f(ph.wave.ray);
        return true;
    }

    // A photon that kept its state near the optic axis becomes the ordinary or the extraordinary wave once its
    // direction leaves the cone where the two stay in phase, drawn by the share of its state along each field.
    static void leaveAxisCone(const TraceBase& s, Photon& ph) {
        const Vec3 k = toVec3(ph.d);
        if (s.nearOpticAxis(k)) return;
        const UniaxialMedium crystal = s.crystal(ph.n, ph.nE);
        const PlaneWave ordinary = ordinaryWave(crystal, k);
        const float toOrdinary = analyserShare(ph.pol, ph.d, Vec3f(ordinary.field));
        ph.wave = ph.rng.uniform() < toOrdinary ? ordinary : extraordinaryWave(crystal, k);
        ph.d = Vec3f(ph.wave.ray);
        ph.coherent = false;
    }

    // step() in a birefringent stone, the exit search done: the wave leaves into the air (its state from the
    // s and p amplitudes) or reflects as the ordinary or the extraordinary wave, by their energy shares.
    // `leaving`, where given, is the interface's waves, already found.
    template <class Visitor>
    static bool stepCrystalWave(const TraceBase& s, const SurfaceHit& hit, Visitor& visit, Photon& ph,
                                const uniaxial::LeavingLane* leaving = nullptr) {
        const Vec3 normal = toVec3(s.scene().normal(hit.facet));
        if (!(dot(ph.wave.ray, normal) > 1e-9)) {  // grazing, where float rounding put the exit
            visit.lost(ph.bounces);
            return false;
        }
        if (leaving) return chooseLeavingWave(s, *leaving, hit, visit, ph);
        const InterfaceWaves w = s.biaxial()
                                     ? leaveCrystal(s.biaxialCrystal(ph.nA, ph.n, ph.nE), ph.wave, normal)
                                     : leaveCrystal(s.crystal(ph.n, ph.nE), ph.wave, normal);
        return chooseLeavingWave(s, WavesLeaving{w}, hit, visit, ph);
    }
    // What chooseLeavingWave() reads of leaveCrystal()'s waves (uniaxial::LeavingLane: of the lanes').
    struct WavesLeaving {
        const InterfaceWaves& w;
        double reflectedShare(int j) const { return w.reflected[j].share[0]; }
        double transmittedShare(int j) const { return w.transmitted[j].share[0]; }
        const PlaneWave& reflectedWave(int j) const { return w.reflected[j].wave; }
        Complex transmittedAmplitude(int j) const { return w.transmitted[j].amplitude[0]; }
        const Vec3& transmittedRay() const { return w.transmitted[0].wave.ray; }
        const Vec3& transmittedField() const { return w.transmitted[0].wave.field; }
    };
    // The wave a photon's draw picks among a leaving's (uniaxial::drawWave): -1 out through the s and p
    // waves, 0 or 1 the reflected ordinary or extraordinary wave; or the lanes' draw where they made it.
    template <class Waves>
    static int drawLeavingWave(const Waves& w, Rng& rng) {
        const uniaxial::WaveDraw<double> draw =
            uniaxial::drawWave<double>(rng.uniform(), w.transmittedShare(0), w.transmittedShare(1),
                                       w.reflectedShare(0), w.reflectedShare(1));
        return draw.pair ? -1 : draw.ordinary ? 0 : 1;
    }
    static int drawLeavingWave(const uniaxial::LeavingLane& w, Rng& rng) {
        if (w.drawn == uniaxial::LeavingLane::kNotDrawn)
            return drawLeavingWave<uniaxial::LeavingLane>(w, rng);
        rng.skip();
        return w.drawn;
    }
    // stepCrystalWave() once the interface's waves w are known (WavesLeaving or uniaxial::LeavingLane).
    template <class Visitor, class Waves>
    static bool chooseLeavingWave(const TraceBase& s, const Waves& w, const SurfaceHit& hit, Visitor& visit,
                                  Photon& ph) {
        const Vec3f p = ph.p + ph.d * hit.t;
        const int wave = drawLeavingWave(w, ph.rng);
        if (wave < 0) {
            const Vec3f dir(w.transmittedRay());
            // The state it leaves in, for a visitor that reads it (the photon goes no further).
            if constexpr (requires { visit.exitPolarization(ph.pol, dir); }) {
                ph.pol = {stokesOf(w.transmittedAmplitude(0), w.transmittedAmplitude(1)),
                          Vec3f(w.transmittedField())};
                visit.exitPolarization(ph.pol, dir);
            }
            visit.exited(hit.facet, p, dir, ph.bounces);
            return false;
        }
        ph.wave = w.reflectedWave(wave);
        ph.p = p;
        ph.d = Vec3f(ph.wave.ray);
        if (s.nearOpticAxis(ph.wave.waveNormal)) {  // the wave, linear along its field, goes on as one state
            ph.coherent = true;
            ph.pol = {Stokes{1, 1, 0, 0}, frameAcross(ph.d, Vec3f(ph.wave.field))};
        }
        visit.internalReflection(hit.facet);
        if (++ph.bounces >= uint32_t(s.settings().maxBounces)) {
            visit.trapped(ph.bounces);
            return false;
        }
        return true;
    }

    template <class Intersector, class Visitor>
    static void walk(const TraceBase& s, const Intersector& isect, uint64_t index, Visitor& visit) {
        Photon ph;
        if (start(s, isect, index, visit, ph)) {
            while (step(s, isect, visit, ph)) {
            }
        }
    }

    // Where one band of a photon went (the fire trace, trace/fire_trace.cpp): a visitor of its walk.
    struct BandExit {
        Vec3f dir;                                      // out of the stone, when Exited
        uint64_t path = 0;                              // the facets it met in order, hashed
        uint32_t facet = 0;                             // the exit's, when Exited
        PhotonOutcome outcome = PhotonOutcome::Missed;  // Trapped for lost photons too

        // Adds the facet met next to a path: two bands took the same path when their hashes agree.
        static uint64_t pathStep(uint64_t path, uint32_t facet) {
            return mix64(path ^ (uint64_t(facet) + 1));
        }
        void missed() { outcome = PhotonOutcome::Missed; }
        void reflectedAtEntry(uint32_t, const Vec3f&, const Vec3f&) {
            outcome = PhotonOutcome::ReflectedAtEntry;
        }
        void entered(uint32_t f) {
            outcome = PhotonOutcome::Trapped;
            path = pathStep(0, f);
        }
        void internalReflection(uint32_t f) { path = pathStep(path, f); }
        void exited(uint32_t f, const Vec3f&, const Vec3f& d, uint32_t) {
            outcome = PhotonOutcome::Exited;
            path = pathStep(path, f);
            facet = f;
            dir = d;
        }
        void trapped(uint32_t) {}
        void lost(uint32_t) {}
        void absorbed(uint32_t) { outcome = PhotonOutcome::Absorbed; }
    };

    // start() for one band of photon `index`, at its index and wavelength: the light ray and every later draw
    // are the plain photon's (the wavelength draw skipped), so a band's draws part from another's only where
    // their choices differ.
    template <class Intersector, class Visitor>
    static bool startBand(const TraceBase& s, const Intersector& isect, uint64_t index, const FireBand& band,
                          Visitor& visit, Photon& ph) {
        ph.rng = Rng(s.settings().seed, index);
        ph.bounces = 0;
        const LightRay ray = s.scene().light().sample(ph.rng);
        if (s.scene().dispersive()) ph.rng.uniform();  // start()'s wavelength
        setBand(s, band, ph);
        return enter(s, isect, ray, visit, ph);
    }

    // Photon `index` at each band of `bands` in turn, one band at a time, into out[k] (the
    // fire trace's reference walk; bandPackets() takes the same steps).
    static void walkBands(const TraceBase& s, uint64_t index, std::span<const FireBand> bands,
                          std::span<BandExit> out) {
        if (s.scene().convex()) {
            walkBands(s, *s.scene().convex(), index, bands, out);
        } else {
            walkBands(s, *s.scene().embree(), index, bands, out);
        }
    }
    template <class Intersector>
    static void walkBands(const TraceBase& s, const Intersector& isect, uint64_t index,
                          std::span<const FireBand> bands, std::span<BandExit> out) {
        for (size_t k = 0; k < bands.size(); ++k) {
            Photon ph;
            if (startBand(s, isect, index, bands[k], out[k], ph)) {
                while (step(s, isect, out[k], ph)) {
                }
            }
        }
    }
    // The bands of photons [begin, end): band k of photon i into exits[(i - begin) * bands.size() + k], as
    // walkBands() gives it. A convex stone's bands are walked a packet at a time, one (photon, band) per
    // lane, unless the stone is birefringent.
    static void blockBands(const TraceBase& s, uint64_t begin, uint64_t end, std::span<const FireBand> bands,
                           std::span<BandExit> exits) {
        if (s.scene().convex() && !s.birefringent()) {
            bandPackets(s, begin, end, bands, exits);
            return;
        }
        for (uint64_t i = begin; i < end; ++i)
            walkBands(s, i, bands, exits.subspan((i - begin) * bands.size(), bands.size()));
    }

    // What the packet walk (photon_packet.cpp, compiled once per SIMD target) reads of the trace and its
    // scene.
    struct PacketScene {
        const TraceBase& trace;
        const ConvexIntersector& convex;
        const ConvexBeamEntry* beam;  // null unless the light is one collimated beam
        const LightModel& light;
        const Material& material;
        const std::vector<Vec3f>& normal;
        float fixedIndex;
        bool dispersive;
        bool polarized;  // photons carry their polarisation
        uint64_t seed;
        uint32_t maxBounces;
    };
    // Photons [begin, end) of a convex stone a packet at a time, one per SIMD lane, on the CPU's best
    // target. Each photon takes exactly the steps walk() takes, so the tally has the same bits. A
    // birefringent stone's lanes share the exit search and meet() their facets one lane at a time.
    static void packets(const TraceBase& s, uint64_t begin, uint64_t end, Tally& t);
    // The packet walk of blockBands(), on a convex stone; and packets() and bandPackets() of the same
    // photons, which start a collimated beam's photons once for both. Neither walks a birefringent stone.
    static void bandPackets(const TraceBase& s, uint64_t begin, uint64_t end, std::span<const FireBand> bands,
                            std::span<BandExit> exits);
    static void packetsAndBands(const TraceBase& s, uint64_t begin, uint64_t end, Tally& t,
                                std::span<const FireBand> bands, std::span<BandExit> exits);
    // packets() with each photon's walk also recorded (TallyWithExits).
    static void packetsWithExits(const TraceBase& s, uint64_t begin, uint64_t end, TallyWithExits& visit);

    // Whether every band's walk is the plain walk of the same photon, bit for bit: when the scene is not
    // dispersive, fireBands() puts each band at the plain photon's index and wavelength and startBand() draws
    // what start() draws. Not in a birefringent stone, whose bands take n_e from n_o (Photon::setIndex).
    static bool bandsArePlain(const TraceBase& s, std::span<const FireBand> bands) {
        const float wavelength = float(Material::kSodiumD);
        return !s.scene().dispersive() && !s.birefringent() &&
               std::ranges::all_of(bands, [&](const FireBand& b) {
                   return std::bit_cast<uint32_t>(b.index) ==
                              std::bit_cast<uint32_t>(s.scene().fixedIndex()) &&
                          std::bit_cast<uint32_t>(b.wavelengthNm) == std::bit_cast<uint32_t>(wavelength);
               });
    }

    // Photons [begin, end) into one thread's tally.
    static void tally(const TraceBase& s, uint64_t begin, uint64_t end, FacetStats& stats) {
        Tally t{s, stats};
        if (s.scene().convex()) {
            packets(s, begin, end, t);
        } else {
            for (uint64_t i = begin; i < end; ++i) walk(s, *s.scene().embree(), i, t);
        }
        stats.photons += end - begin;
    }

    // tally() and blockBands() of photons [begin, end).
    static void tallyAndBands(const TraceBase& s, uint64_t begin, uint64_t end, FacetStats& stats,
                              std::span<const FireBand> bands, std::span<BandExit> exits) {
        if (bandsArePlain(s, bands)) {
            tallyAsBands(s, begin, end, stats, bands.size(), exits);
            return;
        }
        if (!s.scene().convex() || s.birefringent()) {
            tally(s, begin, end, stats);
            blockBands(s, begin, end, bands, exits);
            return;
        }
        Tally t{s, stats};
        packetsAndBands(s, begin, end, t, bands, exits);
        stats.photons += end - begin;
    }

    static void path(const TraceBase& s, uint64_t index, PhotonPath& out) {
        out = PhotonPath{};
        Recorder r{out};
        if (s.scene().convex()) {
            walk(s, *s.scene().convex(), index, r);
        } else {
            walk(s, *s.scene().embree(), index, r);
        }
    }

    struct Tally {
        const TraceBase& s;
        FacetStats& st;

        // The packet walk's visitor of the photon in a lane: the one tally for all.
        Tally& lane(uint32_t) { return *this; }
        void wavelength(float) {}
        void missed() {}
        void reflectedAtEntry(uint32_t facet, const Vec3f&, const Vec3f& dir) {
            ++st.hit;
            ++st.reflectedAtEntry;
            ++st.facets[facet].reflected;
            st.crownReflection += s.crownSide(facet) && dot(dir, s.up()) > 0;
        }
        void entered(uint32_t facet) {
            ++st.hit;
            ++st.entered;
            ++st.facets[facet].entering;
        }
        void internalReflection(uint32_t facet) { ++st.facets[facet].internalReflections; }
        void exited(uint32_t facet, const Vec3f&, const Vec3f& dir, uint32_t) {
            ++st.exited;
            ++st.facets[facet].leaving;
            const float cosUp = std::clamp(dot(dir, s.up()), -1.0f, 1.0f);
            const int bin = s.exitBin()(cosUp);
            const bool crown = s.crownSide(facet);
            ++st.histogram[0][bin];
            ++st.histogram[crown ? 1 : 2][bin];
            if (!crown || cosUp <= 0) return;
            ++st.crownReturn;
            const uint64_t w = uint64_t(double(cosUp) * kWeightScale + 0.5);
            st.weightSum += w;
            st.weightSquareSum += (w * w) >> 30;
            const bool outsideHead = cosUp < s.cosHeadShadow();
            for (int c = 0; c < kConeCount; ++c) st.coneReturn[c] += outsideHead && cosUp >= s.cosCone()[c];
        }
        void trapped(uint32_t) { ++st.trapped; }
        void lost(uint32_t) {
            ++st.trapped;
            ++st.lost;
        }
        void absorbed(uint32_t) { ++st.absorbed; }
    };
    static_assert(kWeightScale == double(1ULL << 30), "weightSquareSum's shift assumes a 2^30 scale");

    // The visitor of a plain walk that also records each photon's walk as a band's: the tally, and photon
    // (lane) id's walk into exits[id * stride].
    struct TallyWithExit {
        Tally& tally;
        BandExit* exit;
        void wavelength(float w) { tally.wavelength(w); }
        void missed() {
            tally.missed();
            exit->missed();
        }
        void reflectedAtEntry(uint32_t facet, const Vec3f& p, const Vec3f& dir) {
            tally.reflectedAtEntry(facet, p, dir);
            exit->reflectedAtEntry(facet, p, dir);
        }
        void entered(uint32_t facet) {
            tally.entered(facet);
            exit->entered(facet);
        }
        void internalReflection(uint32_t facet) {
            tally.internalReflection(facet);
            exit->internalReflection(facet);
        }
        void exited(uint32_t facet, const Vec3f& p, const Vec3f& dir, uint32_t bounces) {
            tally.exited(facet, p, dir, bounces);
            exit->exited(facet, p, dir, bounces);
        }
        void trapped(uint32_t bounces) {
            tally.trapped(bounces);
            exit->trapped(bounces);
        }
        void lost(uint32_t bounces) {
            tally.lost(bounces);
            exit->lost(bounces);
        }
        void absorbed(uint32_t bounces) {
            tally.absorbed(bounces);
            exit->absorbed(bounces);
        }
    };
    struct TallyWithExits {
        std::span<BandExit> exits;
        size_t stride;
        TallyWithExit at;  // the lane's, re-aimed by each lane() call

        TallyWithExit& lane(uint32_t id) {
            at.exit = &exits[id * stride];
            return at;
        }
    };

    // tallyAndBands() where every band is the plain walk (bandsArePlain()): the plain walk once, each
    // photon's copied to its bands.
    static void tallyAsBands(const TraceBase& s, uint64_t begin, uint64_t end, FacetStats& stats,
                             size_t bands, std::span<BandExit> exits) {
        Tally t{s, stats};
        TallyWithExits visit{exits, bands, {t, nullptr}};
        if (s.scene().convex()) {
            packetsWithExits(s, begin, end, visit);
        } else {
            for (uint64_t i = begin; i < end; ++i)
                walk(s, *s.scene().embree(), i, visit.lane(uint32_t(i - begin)));
        }
        stats.photons += end - begin;
        for (size_t i = 0; i < end - begin; ++i)
            std::fill_n(&exits[i * bands + 1], bands - 1, exits[i * bands]);
    }

  private:
    static PacketScene packetScene(const TraceBase& s);

    struct Recorder {
        PhotonPath& out;
        void wavelength(float w) { out.wavelengthNm = w; }
        void missed() { out.outcome = PhotonOutcome::Missed; }
        void reflectedAtEntry(uint32_t facet, const Vec3f& p, const Vec3f& dir) {
            out = {PhotonOutcome::ReflectedAtEntry, out.wavelengthNm, facet, facet, 0, p, dir};
        }
        void entered(uint32_t facet) { out.entryFacet = facet; }
        void internalReflection(uint32_t) {}
        void exited(uint32_t facet, const Vec3f& p, const Vec3f& dir, uint32_t bounces) {
            out.outcome = PhotonOutcome::Exited;
            out.exitFacet = facet;
            out.exitPosition = p;
            out.exitDirection = dir;
            out.bounces = bounces;
        }
        void trapped(uint32_t bounces) {
            out.outcome = PhotonOutcome::Trapped;
            out.bounces = bounces;
        }
        void lost(uint32_t bounces) { trapped(bounces); }
        void absorbed(uint32_t bounces) {
            out.outcome = PhotonOutcome::Absorbed;
            out.bounces = bounces;
        }
    };
};

}  // namespace facetlight
