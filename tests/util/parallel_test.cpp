// The one parallel loop: every index once, per-worker state, progress, exceptions and cancel.
#include "util/parallel.h"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

#include "util/error.h"

using namespace facetlight;

TEST(ParallelForBlocks, RunsEveryIndexExactlyOnceInAlignedBlocks) {
    for (const BlockLoop loop :
         {BlockLoop{0, 1000, 7, 4}, BlockLoop{5, 5000, 64, 3}, BlockLoop{10, 11, 100, 8},
          BlockLoop{0, 4096, 4096, 2}, BlockLoop{3, 3, 10, 4}, BlockLoop{0, 50, 1, 1}}) {
        std::vector<std::atomic<int>> visits(loop.end);
        std::atomic<int> badBlocks{0}, badWorkers{0};
        const bool finished =
            parallelForBlocks(loop, nullptr, [&](int worker, uint64_t first, uint64_t last) {
                badBlocks += (first - loop.begin) % loop.blockSize != 0 || last <= first ||
                             last - first > loop.blockSize || last > loop.end;
                badWorkers += worker < 0 || worker >= loop.workers();
                for (uint64_t i = first; i < last; ++i) ++visits[i];
                return uint64_t(0);
            });
        EXPECT_TRUE(finished);
        EXPECT_EQ(badBlocks.load(), 0);
        EXPECT_EQ(badWorkers.load(), 0);
        for (uint64_t i = 0; i < loop.end; ++i) ASSERT_EQ(visits[i].load(), i >= loop.begin ? 1 : 0) << i;
    }
}

TEST(ParallelForBlocks, StartsNoMoreWorkersThanBlocks) {
    EXPECT_EQ((BlockLoop{0, 10, 4, 8}.workers()), 3);
    EXPECT_EQ((BlockLoop{0, 100, 4, 8}.workers()), 8);
    EXPECT_EQ((BlockLoop{0, 0, 4, 8}.workers()), 1);
    EXPECT_EQ((BlockLoop{0, 100, 4, 0}.workers()), 1);
    EXPECT_EQ((BlockLoop{7, 17, 4, 1}.blocks()), 3u);
}

TEST(ParallelForBlocks, GivesEachWorkerItsOwnStateAndCountsProgress) {
    RunControl control;
    control.startPhase(RunPhase::Tracing, 10'000);
    const WorkerStates<uint64_t> sums = parallelForBlocks(BlockLoop{0, 10'000, 100, 4}, &control, uint64_t(0),
                                                          [](uint64_t& sum, uint64_t first, uint64_t last) {
                                                              for (uint64_t i = first; i < last; ++i)
                                                                  sum += i;
                                                              return last - first;
                                                          });
    EXPECT_TRUE(sums.finished);
    EXPECT_EQ(sums.states.size(), 4u);
    uint64_t total = 0;
    for (uint64_t s : sums.states) total += s;
    EXPECT_EQ(total, 10'000u * 9'999u / 2);
    EXPECT_EQ(control.done(), 10'000u);
}

TEST(ParallelForBlocks, RethrowsAWorkersExceptionOnceAndStopsClaimingBlocks) {
    std::atomic<int> ran{0};
    try {
        parallelForBlocks(BlockLoop{0, 1000, 1, 1}, nullptr, [&](int, uint64_t first, uint64_t) -> uint64_t {
            ++ran;
            if (first == 3) throw Error("block 3 failed");
            return 1;
        });
        FAIL() << "no exception";
    } catch (const Error& e) {
        EXPECT_STREQ(e.what(), "block 3 failed");
    }
    EXPECT_EQ(ran.load(), 4);

    // Every worker throwing still gives one exception, after every worker has stopped.
    ran = 0;
    EXPECT_THROW(parallelForBlocks(BlockLoop{0, 1000, 1, 4}, nullptr,
                                   [&](int, uint64_t, uint64_t) -> uint64_t {
                                       ++ran;
                                       throw std::runtime_error("every block fails");
                                   }),
                 std::runtime_error);
    EXPECT_GE(ran.load(), 1);
    EXPECT_LE(ran.load(), 4);
}

TEST(ParallelForBlocks, StopsWhenCancelled) {
    RunControl control;
    control.cancel();
    std::atomic<int> ran{0};
    EXPECT_FALSE(parallelForBlocks(BlockLoop{0, 100, 1, 3}, &control, [&](int, uint64_t, uint64_t) {
        ++ran;
        return uint64_t(1);
    }));
    EXPECT_EQ(ran.load(), 0);
    EXPECT_EQ(control.done(), 0u);

    // Cancelled while running: the blocks claimed before it finish, no later one starts.
    RunControl midway;
    EXPECT_FALSE(
        parallelForBlocks(BlockLoop{0, 100, 10, 1}, &midway, [&](int, uint64_t first, uint64_t last) {
            if (first == 30) midway.cancel();
            return last - first;
        }));
    EXPECT_EQ(midway.done(), 40u);

    // A cancel after the last block was claimed leaves the loop finished.
    RunControl late;
    EXPECT_TRUE(parallelForBlocks(BlockLoop{0, 100, 10, 1}, &late, [&](int, uint64_t first, uint64_t last) {
        if (last == 100) late.cancel();
        return last - first;
    }));
}
