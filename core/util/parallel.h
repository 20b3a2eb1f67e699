#pragma once
// The one parallel loop. The tracer, the photon pass, the renderer and the photon map's tree build cut their
// work into blocks of consecutive indices (photons, tiles, subtrees); workers claim the blocks one at a time
// from a single atomic counter, each with state of its own, so a block's result never depends on which
// worker ran it or how many there were.
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>
#include <vector>

#include "util/run_control.h"

namespace facetlight {

// The indices [begin, end) in blocks of `blockSize` counted from begin (the last may be shorter), run on up
// to `threads` workers.
struct BlockLoop {
    uint64_t begin = 0, end = 0;
    uint64_t blockSize = 1;
    int threads = 1;

    uint64_t blocks() const;
    // The workers the loop runs on: `threads`, but no more than there are blocks, and at least 1 (the calling
    // thread is worker 0).
    int workers() const;
};

// Calls body(worker, first, last) once for every block [first, last) of the loop, on loop.workers() threads;
// `worker` in [0, workers()) names the thread that runs it. The body returns the units of progress the block
// made (photons, pixels), added to control->done(). A worker checks control->cancelled() before claiming a
// block and stops when it is set. The first exception a body throws stops every worker from claiming more
// and is rethrown here once all have stopped; Error when the threads cannot be started. Returns whether every
// block ran (false: cancelled). control may be null.
bool parallelForBlocks(const BlockLoop& loop, RunControl* control,
                       const std::function<uint64_t(int worker, uint64_t first, uint64_t last)>& body);

template <class State>
struct WorkerStates {
    std::vector<State> states;  // one per worker, for the caller to merge
    bool finished = false;      // every block ran
};

// The same with a state per worker, each a copy of `initial` on cache lines of its own: body(state, first,
// last) returns the units of progress, as above.
template <class State, class Body>
WorkerStates<State> parallelForBlocks(const BlockLoop& loop, RunControl* control, const State& initial,
                                      Body&& body) {
    struct alignas(64) Slot {
        State state;
    };
    std::vector<std::unique_ptr<Slot>> slots;
    for (int w = 0; w < loop.workers(); ++w) slots.push_back(std::make_unique<Slot>(Slot{initial}));
    WorkerStates<State> out;
    out.finished = parallelForBlocks(loop, control, [&](int worker, uint64_t first, uint64_t last) {
        return body(slots[worker]->state, first, last);
    });
    for (auto& slot : slots) out.states.push_back(std::move(slot->state));
    return out;
}

}  // namespace facetlight
