#include "trace/distributed_trace.h"

#include <algorithm>
#include <chrono>

namespace facetlight {

uint64_t localPhotons(const Communicator& comm, uint64_t photons) {
    const IndexRange blocks = partition(blockCount(photons), comm.rank(), comm.size());
    return std::min(blocks.end * kPhotonBlock, photons) - std::min(blocks.begin * kPhotonBlock, photons);
}

TraceResult traceDistributed(Communicator& comm, const TraceBase& trace, RunControl* control) {
    const auto start = std::chrono::steady_clock::now();
    const TraceSettings& settings = trace.settings();
    const size_t facets = trace.scene().stone().facets.size();
    TraceResult result{FacetStats(facets), {0, settings.threads}, false, std::nullopt};
    const IndexRange blocks = partition(blockCount(settings.photons), comm.rank(), comm.size());
    if (settings.fire.enabled) result.fire = FireStats(facets);
    FireStats* fire = result.fire ? &*result.fire : nullptr;
    const bool finished =
        traceBlocks(trace, blocks.begin, blocks.end, settings.threads, result.stats, control, fire);

    // The fire tallies follow the trace's; the last element counts cancelled ranks, so a cancel anywhere is
    // seen on rank 0.
    std::vector<uint64_t> tallies = result.stats.tallies();
    const size_t traceTallies = tallies.size();
    if (fire) {
        const std::vector<uint64_t> fireTallies = fire->tallies();
        tallies.insert(tallies.end(), fireTallies.begin(), fireTallies.end());
    }
    tallies.push_back(finished ? 0 : 1);
    comm.sumToRoot(tallies);
    if (comm.isRoot()) {
        result.cancelled = tallies.back() != 0;
        tallies.pop_back();
        const std::span<const uint64_t> all(tallies);
        result.stats.setTallies(all.first(traceTallies));
        if (fire) fire->setTallies(all.subspan(traceTallies));
    } else {
        result.cancelled = !finished;
    }
    result.timing.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

}  // namespace facetlight
