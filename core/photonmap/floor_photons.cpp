#include "photonmap/floor_photons.h"

#include <algorithm>
#include <memory>
#include <thread>

#include "util/error.h"

namespace facetlight {

FloorPhotons traceFloorPhotons(const Scene& scene, const TraceScene& trace, uint64_t count, int threads,
                               std::atomic<uint64_t>* photonsDone, const std::atomic<bool>* cancel) {
    return traceFloorPhotons(scene, trace, count, 0, blockCount(count), threads, photonsDone, cancel);
}

FloorPhotons traceFloorPhotons(const Scene& scene, const TraceScene& trace, uint64_t count,
                               uint64_t firstBlock, uint64_t lastBlock, int threads,
                               std::atomic<uint64_t>* photonsDone, const std::atomic<bool>* cancel) {
    const float power = float(scene.photonPower(count));
    lastBlock = std::min(lastBlock, blockCount(count));
    firstBlock = std::min(firstBlock, lastBlock);
    const uint64_t blocks = lastBlock - firstBlock;
    const uint64_t first = firstBlock * kPhotonBlock,
                   local = std::min(lastBlock * kPhotonBlock, count) - first;
    const int workers =
        int(std::clamp<uint64_t>(uint64_t(std::max(threads, 1)), 1, std::max<uint64_t>(blocks, 1)));
    // One slot per photon of the range, filled by whichever thread traces it and compacted in index order
    // afterwards.
    std::vector<Photon> slots(local);
    std::vector<uint8_t> landed(local);
    std::vector<std::unique_ptr<AngularHistogram>> histograms;
    for (int t = 0; t < workers; ++t) histograms.push_back(std::make_unique<AngularHistogram>());
    std::atomic<uint64_t> nextBlock{0}, blocksDone{0};
    std::atomic<bool> abort{false};

    auto work = [&](AngularHistogram& histogram) {
        PhotonPath path;
        Vec3 position;
        for (;;) {
            if (abort.load(std::memory_order_relaxed)) return;
            if (cancel && cancel->load(std::memory_order_relaxed)) return;
            const uint64_t block = firstBlock + nextBlock.fetch_add(1, std::memory_order_relaxed);
            if (block >= lastBlock) return;
            const uint64_t begin = block * kPhotonBlock, end = std::min(begin + kPhotonBlock, count);
            for (uint64_t i = begin; i < end; ++i) {
                tracePhoton(trace, i, path);
                const Vec3 dir{path.exitDirection.x, path.exitDirection.y, path.exitDirection.z};
                if (path.outcome == PhotonOutcome::Exited) {
                    const Region r = scene.stone().facets[path.exitFacet].region;
                    if (r == Region::Table || r == Region::Crown) histogram.add(scene.toWorld(dir));
                }
                if (scene.landOnFloor(path, position)) {
                    slots[i - first] =
                        Photon::make(position, power, dir, scene.dispersive() ? path.wavelengthNm : 0.0);
                    landed[i - first] = 1;
                }
            }
            blocksDone.fetch_add(1, std::memory_order_relaxed);
            if (photonsDone) photonsDone->fetch_add(end - begin, std::memory_order_relaxed);
        }
    };
    std::vector<std::thread> pool;
    try {
        for (int t = 1; t < workers; ++t) pool.emplace_back(work, std::ref(*histograms[t]));
    } catch (...) {
        abort = true;
        for (std::thread& th : pool) th.join();
        throw Error("cannot start " + std::to_string(workers) + " threads");
    }
    work(*histograms[0]);
    for (std::thread& th : pool) th.join();

    FloorPhotons out;
    out.cancelled = blocksDone.load() != blocks;
    out.traced = local;
    for (const auto& h : histograms) out.crownExits.merge(*h);
    size_t stored = 0;
    for (uint64_t i = 0; i < local; ++i) stored += landed[i];
    out.caustic.reserve(stored);
    for (uint64_t i = 0; i < local; ++i) {
        if (landed[i]) out.caustic.push_back(slots[i]);
    }
    return out;
}

FloorPhotons traceFloorPhotons(Communicator& comm, const Scene& scene, const TraceScene& trace,
                               uint64_t count, int threads, std::atomic<uint64_t>* photonsDone,
                               const std::atomic<bool>* cancel) {
    const IndexRange blocks = partition(blockCount(count), comm.rank(), comm.size());
    FloorPhotons out =
        traceFloorPhotons(scene, trace, count, blocks.begin, blocks.end, threads, photonsDone, cancel);
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
