#include "util/parallel.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <string>
#include <thread>

#include "util/error.h"

namespace facetlight {

uint64_t BlockLoop::blocks() const {
    const uint64_t size = std::max<uint64_t>(blockSize, 1);
    return end > begin ? (end - begin + size - 1) / size : 0;
}

int BlockLoop::workers() const {
    return int(std::clamp<uint64_t>(uint64_t(std::max(threads, 1)), 1, std::max<uint64_t>(blocks(), 1)));
}

bool parallelForBlocks(const BlockLoop& loop, RunControl* control,
                       const std::function<uint64_t(int, uint64_t, uint64_t)>& body) {
    const uint64_t blocks = loop.blocks(), size = std::max<uint64_t>(loop.blockSize, 1);
    const int workers = loop.workers();
    // Each on a cache line of its own: claimed by every worker, but apart from what the bodies write.
    alignas(64) std::atomic<uint64_t> next{0};
    alignas(64) std::atomic<uint64_t> blocksDone{0};
    alignas(64) std::atomic<bool> stop{false};
    std::exception_ptr failure;
    std::once_flag failed;

    auto work = [&](int worker) {
        for (;;) {
            if (stop.load(std::memory_order_relaxed) || (control && control->cancelled())) return;
            const uint64_t block = next.fetch_add(1, std::memory_order_relaxed);
            if (block >= blocks) return;
            const uint64_t first = loop.begin + block * size, last = std::min(first + size, loop.end);
            try {
                const uint64_t units = body(worker, first, last);
                if (control) control->advance(units);
            } catch (...) {
                std::call_once(failed, [&] { failure = std::current_exception(); });
                stop.store(true, std::memory_order_relaxed);
                return;
            }
            blocksDone.fetch_add(1, std::memory_order_relaxed);
        }
    };

    std::vector<std::thread> pool;
    try {
        for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
    } catch (...) {
        stop = true;
        for (std::thread& t : pool) t.join();
        throw Error("cannot start " + std::to_string(workers) + " threads");
    }
    work(0);
    for (std::thread& t : pool) t.join();
    if (failure) std::rethrow_exception(failure);
    return blocksDone.load() == blocks;
}

}  // namespace facetlight
