#include "floor_photons.h"

#include <algorithm>
#include <memory>
#include <thread>

#include "error.h"

namespace facetlight {

FloorPhotons traceFloorPhotons(const Scene& scene, const TraceScene& trace, uint64_t count, int threads,
                               std::atomic<uint64_t>* photonsDone, const std::atomic<bool>* cancel) {
    const float power = float(scene.photonPower(count));
    const uint64_t blocks = blockCount(count);
    const int workers =
        int(std::clamp<uint64_t>(uint64_t(std::max(threads, 1)), 1, std::max<uint64_t>(blocks, 1)));
    // One slot per photon, filled by whichever thread traces it and compacted in index order afterwards.
    std::vector<Photon> slots(count);
    std::vector<uint8_t> landed(count);
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
            const uint64_t block = nextBlock.fetch_add(1, std::memory_order_relaxed);
            if (block >= blocks) return;
            const uint64_t begin = block * kPhotonBlock, end = std::min(begin + kPhotonBlock, count);
            for (uint64_t i = begin; i < end; ++i) {
                tracePhoton(trace, i, path);
                const Vec3 dir{path.exitDirection.x, path.exitDirection.y, path.exitDirection.z};
                if (path.outcome == PhotonOutcome::Exited) {
                    const Region r = scene.stone().facets[path.exitFacet].region;
                    if (r == Region::Table || r == Region::Crown) histogram.add(scene.toWorld(dir));
                }
                if (scene.landOnFloor(path, position)) {
                    slots[i] =
                        Photon::make(position, power, dir, scene.dispersive() ? path.wavelengthNm : 0.0);
                    landed[i] = 1;
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
    out.traced = count;
    for (const auto& h : histograms) out.crownExits.merge(*h);
    size_t stored = 0;
    for (uint64_t i = 0; i < count; ++i) stored += landed[i];
    out.caustic.reserve(stored);
    for (uint64_t i = 0; i < count; ++i) {
        if (landed[i]) out.caustic.push_back(slots[i]);
    }
    return out;
}

}  // namespace facetlight
