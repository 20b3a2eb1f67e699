#include "trace/photon_tracer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "intersect/convex_intersector.h"
#include "intersect/embree_intersector.h"
#include "trace/detail/photon_walker.h"
#include "util/error.h"

namespace facetlight {

TraceScene::TraceScene(const Stone& stone, const TraceSettings& settings)
    : stone_(stone),
      settings_(settings),
      material_(settings.n ? Material::constant(*settings.n) : Material::byName(settings.material)),
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
        // The same float operations as PhotonWalker::start, so a photon's fate is bit for bit the same.
        const Vec3f d(light_.direction());
        const float eta = 1.0f / fixedIndex_;
        for (const Vec3f& normal : normal_) {
            const float cosI = std::clamp(-dot(d, normal), 0.0f, 1.0f);
            const FresnelResult fr = fresnel(cosI, eta);
            fixedEntry_.push_back({fr.reflectance, PhotonWalker::reflectOff(d, normal, cosI),
                                   PhotonWalker::refractIn(d, normal, eta, cosI, fr.cosT)});
        }
    }
}

TraceScene::~TraceScene() = default;

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
