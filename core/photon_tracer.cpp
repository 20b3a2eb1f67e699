#include "photon_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "convex_intersector.h"
#include "embree_intersector.h"
#include "error.h"
#include "random.h"

namespace facetlight {

TraceScene::TraceScene(const Stone& stone, const TraceSettings& settings)
    : stone_(stone),
      settings_(settings),
      material_((settings.validate(),
                 settings.n ? Material::constant(*settings.n) : Material::byName(settings.material))),
      light_(settings.light, stone),
      fixedIndex_(float(material_.indexD())) {
    if (stone.facets.empty()) throw Error("stone '" + stone.name + "' has no facets");
    for (const Facet& f : stone.facets) {
        facetRegion_.push_back(f.region);
        normal_.emplace_back(f.normal);
    }
    const double tilt = radians(settings.light.tiltDeg);
    up_ = Vec3f(Vec3{0, std::sin(tilt), std::cos(tilt)});
    cosHeadShadow_ =
        settings.light.headShadowDeg > 0 ? float(std::cos(radians(settings.light.headShadowDeg))) : 2.0f;
    for (int c = 0; c < kConeCount; ++c) cosCone_[c] = float(std::cos(radians(kConeDegrees[c])));

    IntersectorKind kind = settings.intersector;
    if (kind == IntersectorKind::Auto)
        kind = stone.convex ? IntersectorKind::Convex : IntersectorKind::Embree;
    if (kind == IntersectorKind::Convex) {
        if (!stone.convex)
            throw Error("intersector 'convex' needs a convex stone; '" + stone.name + "' is not");
        convex_ = std::make_unique<ConvexIntersector>(stone);
        if (light_.collimated()) beam_ = std::make_unique<ConvexBeamEntry>(stone, Vec3f(light_.direction()));
    } else {
        embree_ = std::make_unique<EmbreeIntersector>(stone);
    }
    if (light_.collimated() && !perPhotonIndex()) {
        // The same float operations as PhotonWalker::walk, so a photon's fate is bit for bit the same.
        const Vec3f d(light_.direction());
        const float eta = 1.0f / fixedIndex_;
        for (const Vec3f& normal : normal_) {
            const float cosI = std::clamp(-dot(d, normal), 0.0f, 1.0f);
            const FresnelResult fr = fresnel(cosI, eta);
            fixedEntry_.push_back({fr.reflectance, d + normal * (2 * cosI),
                                   normalize(d * eta + normal * (eta * cosI - fr.cosT))});
        }
    }
}

TraceScene::~TraceScene() = default;

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
    static bool start(const TraceScene& s, const Intersector& isect, uint64_t index, Visitor& visit,
                      Photon& ph) {
        ph.rng = Rng(s.settings_.seed, index);
        ph.bounces = 0;
        const LightRay ray = s.light_.sample(ph.rng);
        float wavelength = float(Material::kSodiumD);
        ph.n = s.fixedIndex_;
        if (s.perPhotonIndex()) {
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
            const TraceScene::FixedEntry& e = s.fixedEntry_[hit.facet];
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
                visit.reflectedAtEntry(hit.facet, p, d + normal * (2 * cosI));
                return false;
            }
            d = normalize(d * eta + normal * (eta * cosI - fr.cosT));
        }
        visit.entered(hit.facet);
        ph.p = p;
        ph.d = d;
        return true;
    }

    // The photon's next interaction inside; true while it stays inside.
    template <class Intersector, class Visitor>
    static bool step(const TraceScene& s, const Intersector& isect, Visitor& visit, Photon& ph) {
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
            visit.exited(hit.facet, p, normalize(d * n - normal * (n * cosI - fr.cosT)), ph.bounces);
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

    template <class Intersector, class Visitor>
    static void walk(const TraceScene& s, const Intersector& isect, uint64_t index, Visitor& visit) {
        Photon ph;
        if (start(s, isect, index, visit, ph)) {
            while (step(s, isect, visit, ph)) {
            }
        }
    }

    // Photons [begin, end) with a few in flight at once: their interactions are independent chains of
    // dependent operations, which the core overlaps. Each photon takes exactly the steps walk() takes.
    template <class Intersector>
    static void interleave(const TraceScene& s, const Intersector& isect, uint64_t begin, uint64_t end,
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

    // Photons [begin, end) into one thread's tally.
    static void tally(const TraceScene& s, uint64_t begin, uint64_t end, FacetStats& stats) {
        Tally t{s, stats};
        if (s.convex_) {
            interleave(s, *s.convex_, begin, end, t);
        } else {
            for (uint64_t i = begin; i < end; ++i) walk(s, *s.embree_, i, t);
        }
        stats.photons += end - begin;
    }

    static void path(const TraceScene& s, uint64_t index, PhotonPath& out) {
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
        const TraceScene& s;
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

void tracePhoton(const TraceScene& scene, uint64_t index, PhotonPath& out) {
    PhotonWalker::path(scene, index, out);
}

bool traceBlocks(const TraceScene& scene, uint64_t firstBlock, uint64_t lastBlock, int threads,
                 FacetStats& stats, TraceControl* control) {
    const uint64_t photons = scene.settings().photons;
    lastBlock = std::min(lastBlock, blockCount(photons));
    if (firstBlock >= lastBlock) return true;
    if (stats.facets.size() != scene.stone().facets.size()) stats = FacetStats(scene.stone().facets.size());
    const int workers = int(std::clamp<uint64_t>(uint64_t(std::max(threads, 1)), 1, lastBlock - firstBlock));

    // Every tally is allocated before the loop, each on cache lines of its own (FacetStats is alignas(64)).
    std::vector<std::unique_ptr<FacetStats>> tallies;
    for (int t = 0; t < workers; ++t)
        tallies.push_back(std::make_unique<FacetStats>(scene.stone().facets.size()));
    std::atomic<uint64_t> nextBlock{firstBlock}, blocksDone{0};
    std::atomic<bool> abort{false};

    auto work = [&](FacetStats& tally) {
        for (;;) {
            if (abort.load(std::memory_order_relaxed)) return;
            if (control && control->cancel.load(std::memory_order_relaxed)) return;
            const uint64_t block = nextBlock.fetch_add(1, std::memory_order_relaxed);
            if (block >= lastBlock) return;
            const uint64_t begin = block * kPhotonBlock, end = std::min(begin + kPhotonBlock, photons);
            PhotonWalker::tally(scene, begin, end, tally);
            blocksDone.fetch_add(1, std::memory_order_relaxed);
            if (control) control->photonsDone.fetch_add(end - begin, std::memory_order_relaxed);
        }
    };

    std::vector<std::thread> pool;
    try {
        for (int t = 1; t < workers; ++t) pool.emplace_back(work, std::ref(*tallies[t]));
    } catch (...) {
        abort = true;
        for (std::thread& th : pool) th.join();
        throw Error("cannot start " + std::to_string(workers) + " threads");
    }
    work(*tallies[0]);
    for (std::thread& th : pool) th.join();

    for (const auto& tally : tallies) stats.merge(*tally);
    return blocksDone.load() == lastBlock - firstBlock;
}

TraceResult trace(const Stone& stone, const TraceSettings& settings, TraceControl* control) {
    const TraceScene scene(stone, settings);
    TraceResult result{FacetStats(stone.facets.size()), {0, settings.threads}, false};
    const auto start = std::chrono::steady_clock::now();
    result.cancelled =
        !traceBlocks(scene, 0, blockCount(settings.photons), settings.threads, result.stats, control);
    result.timing.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace facetlight
