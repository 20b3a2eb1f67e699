#include "trace/photon_tracer.h"

#include <algorithm>
#include <chrono>

#include "trace/detail/photon_walker.h"
#include "trace/fire_trace.h"
#include "util/parallel.h"

namespace facetlight {

void tracePhoton(const Scene& scene, uint64_t index, PhotonPath& out) {
    PhotonWalker::path(scene, index, out);
}

bool traceBlocks(const Scene& scene, uint64_t firstBlock, uint64_t lastBlock, int threads, FacetStats& stats,
                 RunControl* control, FireStats* fire) {
    const uint64_t photons = scene.settings().photons;
    lastBlock = std::min(lastBlock, blockCount(photons));
    if (firstBlock >= lastBlock) return true;
    const size_t facets = scene.stone().facets.size();
    if (stats.facets.size() != facets) stats = FacetStats(facets);
    if (fire && fire->colouredByFacet.size() != facets) *fire = FireStats(facets);
    const BlockLoop loop{firstBlock * kPhotonBlock, std::min(lastBlock * kPhotonBlock, photons), kPhotonBlock,
                         threads};
    struct Tallies {
        FacetStats stats;
        FireStats fire;
    };
    const WorkerStates<Tallies> tallies =
        parallelForBlocks(loop, control, Tallies{FacetStats(facets), FireStats(fire ? facets : 0)},
                          [&](Tallies& tally, uint64_t begin, uint64_t end) {
                              PhotonWalker::tally(scene, begin, end, tally.stats);
                              if (fire) traceFire(scene, begin, end, tally.fire);
                              return end - begin;
                          });
    for (const Tallies& tally : tallies.states) {
        stats.merge(tally.stats);
        if (fire) fire->merge(tally.fire);
    }
    return tallies.finished;
}

TraceResult trace(const Scene& scene, RunControl* control) {
    const TraceSettings& settings = scene.settings();
    TraceResult result{FacetStats(scene.stone().facets.size()), {0, settings.threads}, false, std::nullopt};
    if (settings.fire.enabled) result.fire = FireStats(scene.stone().facets.size());
    const auto start = std::chrono::steady_clock::now();
    result.cancelled = !traceBlocks(scene, 0, blockCount(settings.photons), settings.threads, result.stats,
                                    control, result.fire ? &*result.fire : nullptr);
    result.timing.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace facetlight
