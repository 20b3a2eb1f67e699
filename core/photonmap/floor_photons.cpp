#include "photonmap/floor_photons.h"

#include <algorithm>

#include "util/parallel.h"

namespace facetlight {

FloorPhotons traceFloorPhotons(const TraceBase& trace, uint64_t count, int threads, RunControl* control) {
    return traceFloorPhotons(trace, count, 0, blockCount(count), threads, control);
}

FloorPhotons traceFloorPhotons(const TraceBase& trace, uint64_t count, uint64_t firstBlock,
                               uint64_t lastBlock, int threads, RunControl* control) {
    const Scene& scene = trace.scene();
    const float power = float(scene.photonPower(count));
    lastBlock = std::min(lastBlock, blockCount(count));
    firstBlock = std::min(firstBlock, lastBlock);
    const uint64_t first = firstBlock * kPhotonBlock,
                   local = std::min(lastBlock * kPhotonBlock, count) - first;
    // One slot per photon of the range, filled by whichever worker traces it and compacted in index order
    // afterwards.
    std::vector<Photon> slots(local);
    std::vector<uint8_t> landed(local);
    const BlockLoop loop{first, first + local, kPhotonBlock, threads};
    const WorkerStates<AngularHistogram> histograms = parallelForBlocks(
        loop, control, AngularHistogram{}, [&](AngularHistogram& histogram, uint64_t begin, uint64_t end) {
            PhotonPath path;
            Vec3 position;
            for (uint64_t i = begin; i < end; ++i) {
                tracePhoton(trace, i, path);
                const Vec3 dir{path.exitDirection.x, path.exitDirection.y, path.exitDirection.z};
                if (path.outcome == PhotonOutcome::Exited) {
                    const Region r = scene.stone().facets[path.exitFacet].region;
                    if (r == Region::Table || r == Region::Crown) histogram.add(scene.toWorld(dir));
                }
                const bool leftStone =
                    path.outcome == PhotonOutcome::Exited || path.outcome == PhotonOutcome::ReflectedAtEntry;
                if (leftStone && scene.landOnFloor(path.exitPosition, path.exitDirection, position)) {
                    slots[i - first] =
                        Photon::make(position, power, dir, scene.dispersive() ? path.wavelengthNm : 0.0);
                    landed[i - first] = 1;
                }
            }
            return end - begin;
        });

    FloorPhotons out;
    out.cancelled = !histograms.finished;
    out.traced = local;
    for (const AngularHistogram& h : histograms.states) out.crownExits.merge(h);
    size_t stored = 0;
    for (uint64_t i = 0; i < local; ++i) stored += landed[i];
    out.caustic.reserve(stored);
    for (uint64_t i = 0; i < local; ++i) {
        if (landed[i]) out.caustic.push_back(slots[i]);
    }
    return out;
}

FloorPhotons traceFloorPhotons(Communicator& comm, const TraceBase& trace, uint64_t count, int threads,
                               RunControl* control) {
    const IndexRange blocks = partition(blockCount(count), comm.rank(), comm.size());
    FloorPhotons out = traceFloorPhotons(trace, count, blocks.begin, blocks.end, threads, control);
    if (comm.size() == 1) return out;
    out.cancelled = anyRank(comm, out.cancelled);
    if (out.cancelled) return out;

    // Ranks hold consecutive block ranges, so rank order is photon-index order.
    const std::vector<std::string> parts = comm.allGather(asBytes(std::span<const Photon>(out.caustic)));
    out.caustic.clear();
    size_t bytes = 0;
    for (const std::string& part : parts) bytes += part.size();
    out.caustic.reserve(bytes / sizeof(Photon));
    for (const std::string& part : parts) appendFromBytes(part, out.caustic);

    // Integer counts: the sum is the single-process histogram exactly. The tail carries the traced photons.
    std::vector<uint64_t> tallies = out.crownExits.tallies();
    tallies.push_back(out.traced);
    comm.sumToRoot(tallies);
    if (comm.isRoot()) {
        out.traced = tallies.back();
        tallies.pop_back();
        out.crownExits.setTallies(tallies);
    }
    return out;
}

}  // namespace facetlight
