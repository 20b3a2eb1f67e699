#pragma once
// Inside the tracer (not for use outside core/): the walk of photons through a stone, shared by the
// per-photon path, the interleaved walk and the packet walk of photon_packet.cpp.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "intersect/convex_intersector.h"
#include "intersect/embree_intersector.h"
#include "optics/fresnel.h"
#include "trace/photon_tracer.h"
#include "util/random.h"
#include "util/simd.h"

namespace facetlight {

// The walk of one photon, written once and specialised by intersector (no virtual call per ray) and by what
// is recorded (a tally for statistics, a path for the renderer).
class PhotonWalker {
    struct Tally;

  public:
    // A photon inside the stone, between two interactions.
    struct Photon {
        Rng rng{0, 0};
        Vec3f p, d;
        float n = 0;
        uint32_t bounces = 0;
    };

    // Draws photon `index` and takes it to the stone; true when it is inside and has to be stepped on.
    template <class Intersector, class Visitor>
    static bool start(const Scene& s, const Intersector& isect, uint64_t index, Visitor& visit,
                      Photon& ph) {
        ph.rng = Rng(s.settings_.seed, index);
        ph.bounces = 0;
        const LightRay ray = s.light_.sample(ph.rng);
        float wavelength = float(Material::kSodiumD);
        ph.n = s.fixedIndex_;
        if (s.dispersive()) {
            wavelength = 380.0f + 400.0f * ph.rng.uniform();
            ph.n = float(s.material_.index(wavelength));
        }
        visit.wavelength(wavelength);

        Vec3f d(ray.direction), p(ray.origin);
        SurfaceHit hit;
        if (!(s.beam_ ? s.beam_->enter(p, hit) : isect.enter(p, d, hit))) {
            visit.missed();
            return false;
        }
        p = p + d * hit.t;
        if (!s.fixedEntry_.empty()) {
            const Scene::FixedEntry& e = s.fixedEntry_[hit.facet];
            if (ph.rng.uniform() < e.reflectance) {
                visit.reflectedAtEntry(hit.facet, p, e.reflected);
                return false;
            }
            d = e.refracted;
        } else {
            const Vec3f normal = s.normal_[hit.facet];
            const float cosI = std::clamp(-dot(d, normal), 0.0f, 1.0f);
            const float eta = 1.0f / ph.n;
            const FresnelResult fr = fresnel(cosI, eta);
            if (ph.rng.uniform() < fr.reflectance) {
                visit.reflectedAtEntry(hit.facet, p, reflectOff(d, normal, cosI));
                return false;
            }
            d = refractIn(d, normal, eta, cosI, fr.cosT);
        }
        visit.entered(hit.facet);
        ph.p = p;
        ph.d = d;
        return true;
    }

    // The photon's next interaction inside; true while it stays inside.
    template <class Intersector, class Visitor>
    static bool step(const Scene& s, const Intersector& isect, Visitor& visit, Photon& ph) {
        SurfaceHit hit;
        if (!isect.leave(ph.p, ph.d, hit)) {
            visit.lost(ph.bounces);
            return false;
        }
        const Vec3f p = ph.p + ph.d * hit.t, d = ph.d;
        const Vec3f normal = s.normal_[hit.facet];
        const float cosI = std::clamp(dot(d, normal), 0.0f, 1.0f), n = ph.n;
        const FresnelResult fr = fresnel(cosI, n);
        if (!fr.totalInternal && ph.rng.uniform() >= fr.reflectance) {
            visit.exited(hit.facet, p, refractOut(d, normal, n, cosI, fr.cosT), ph.bounces);
            return false;
        }
        ph.p = p;
        ph.d = d - normal * (2 * cosI);
        visit.internalReflection(hit.facet);
        if (++ph.bounces >= uint32_t(s.settings_.maxBounces)) {
            visit.trapped(ph.bounces);
            return false;
        }
        return true;
    }

    // A ray from outside at cos(incidence) cosI off a facet of outward normal `normal`, and into it with
    // eta = 1 / n (Snell's law).
    static Vec3f reflectOff(const Vec3f& d, const Vec3f& normal, float cosI) {
        return d + normal * (2 * cosI);
    }
    static Vec3f refractIn(const Vec3f& d, const Vec3f& normal, float eta, float cosI, float cosT) {
        return normalize(d * eta + normal * (eta * cosI - cosT));
    }
    // Out of the stone (index n) into air through a facet of outward normal `normal` (Snell's law).
    static Vec3f refractOut(const Vec3f& d, const Vec3f& normal, float n, float cosI, float cosT) {
        return normalize(d * n - normal * (n * cosI - cosT));
    }

    template <class Intersector, class Visitor>
    static void walk(const Scene& s, const Intersector& isect, uint64_t index, Visitor& visit) {
        Photon ph;
        if (start(s, isect, index, visit, ph)) {
            while (step(s, isect, visit, ph)) {
            }
        }
    }

    // Photons [begin, end) with a few in flight at once, where packets are not built (no AVX-512): their
    // interactions are independent chains of dependent operations, which the core overlaps. Each photon
    // takes exactly the steps walk() takes.
    template <class Intersector>
    static void interleave(const Scene& s, const Intersector& isect, uint64_t begin, uint64_t end,
                           Tally& t) {
        constexpr int kLanes = 4;
        Photon lane[kLanes];
        bool live[kLanes];
        uint64_t next = begin;
        auto refill = [&](int k) {
            live[k] = false;
            while (!live[k] && next < end) live[k] = start(s, isect, next++, t, lane[k]);
        };
        int active = 0;
        for (int k = 0; k < kLanes; ++k) {
            refill(k);
            active += live[k];
        }
        while (active > 0) {
            for (int k = 0; k < kLanes; ++k) {
                if (!live[k] || step(s, isect, t, lane[k])) continue;
                refill(k);
                active -= !live[k];
            }
        }
    }

#if FACETLIGHT_PACKETS
    // Photons [begin, end) of a convex stone sixteen at a time, one per SIMD lane (photon_packet.cpp).
    // Each photon takes exactly the steps walk() takes, so the tally has the same bits.
    static void packets(const Scene& s, uint64_t begin, uint64_t end, Tally& t);
    struct Packet;
    // start() for photons [first, min(first + 16, end)): tallies those that miss or reflect off the stone
    // and makes those that get in live lanes of `started`, which has none live before.
    static void startPacket(const Scene& s, uint64_t first, uint64_t end, Tally& t, Packet& started);
    // step() for every live lane of the packet; the lanes whose photon is done are no longer live.
    static void stepPacket(const Scene& s, Packet& lanes, Tally& t);
#endif

    // Photons [begin, end) into one thread's tally.
    static void tally(const Scene& s, uint64_t begin, uint64_t end, FacetStats& stats) {
        Tally t{s, stats};
        if (s.convex_) {
#if FACETLIGHT_PACKETS
            packets(s, begin, end, t);
#else
            interleave(s, *s.convex_, begin, end, t);
#endif
        } else {
            for (uint64_t i = begin; i < end; ++i) walk(s, *s.embree_, i, t);
        }
        stats.photons += end - begin;
    }

    static void path(const Scene& s, uint64_t index, PhotonPath& out) {
        out = PhotonPath{};
        Recorder r{out};
        if (s.convex_) {
            walk(s, *s.convex_, index, r);
        } else {
            walk(s, *s.embree_, index, r);
        }
    }

  private:
    struct Tally {
        const Scene& s;
        FacetStats& st;

        bool crownSide(uint32_t facet) const {
            const Region r = s.facetRegion_[facet];
            return r == Region::Table || r == Region::Crown;
        }
        void wavelength(float) {}
        void missed() {}
        void reflectedAtEntry(uint32_t facet, const Vec3f&, const Vec3f& dir) {
            ++st.hit;
            ++st.reflectedAtEntry;
            ++st.facets[facet].reflected;
            st.crownReflection += crownSide(facet) && dot(dir, s.up_) > 0;
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
            const float cosUp = std::clamp(dot(dir, s.up_), -1.0f, 1.0f);
            const int bin = s.exitBin_(cosUp);
            const bool crown = crownSide(facet);
            ++st.histogram[0][bin];
            ++st.histogram[crown ? 1 : 2][bin];
            if (!crown || cosUp <= 0) return;
            ++st.crownReturn;
            const uint64_t w = uint64_t(double(cosUp) * kWeightScale + 0.5);
            st.weightSum += w;
            st.weightSquareSum += (w * w) >> 30;
            const bool outsideHead = cosUp < s.cosHeadShadow_;
            for (int c = 0; c < kConeCount; ++c) st.coneReturn[c] += outsideHead && cosUp >= s.cosCone_[c];
        }
        void trapped(uint32_t) { ++st.trapped; }
        void lost(uint32_t) {
            ++st.trapped;
            ++st.lost;
        }
    };
    static_assert(kWeightScale == double(1ULL << 30), "weightSquareSum's shift assumes a 2^30 scale");

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
    };
};

}  // namespace facetlight
