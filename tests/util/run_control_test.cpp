// A run's progress and cancel: phases, counts, and what watchers read while workers advance it.
#include "util/run_control.h"

#include <gtest/gtest.h>

#include <thread>
#include <vector>

#include "cli/terminal_output.h"

using namespace facetlight;

TEST(RunControl, StartsQueuedAndCountsEachPhaseFromZero) {
    RunControl control;
    EXPECT_EQ(control.phase(), RunPhase::Queued);
    EXPECT_EQ(control.fraction(), 0.0);
    control.startPhase(RunPhase::Tracing, 200);
    control.advance(50);
    EXPECT_EQ(control.phase(), RunPhase::Tracing);
    EXPECT_EQ(control.done(), 50u);
    EXPECT_EQ(control.total(), 200u);
    EXPECT_DOUBLE_EQ(control.fraction(), 0.25);
    control.startPhase(RunPhase::Rendering, 10);
    EXPECT_EQ(control.done(), 0u);
    EXPECT_EQ(control.total(), 10u);
    control.show(RunPhase::PhotonMap, 3, 4);
    EXPECT_EQ(control.phase(), RunPhase::PhotonMap);
    EXPECT_DOUBLE_EQ(control.fraction(), 0.75);
}

TEST(RunControl, AdvancesFromManyThreadsWithoutLosingCounts) {
    RunControl control;
    control.startPhase(RunPhase::Tracing, 8 * 100'000);
    std::vector<std::thread> workers;
    for (int t = 0; t < 8; ++t)
        workers.emplace_back([&] {
            for (int i = 0; i < 100'000; ++i) control.advance(1);
        });
    for (std::thread& w : workers) w.join();
    EXPECT_EQ(control.done(), 800'000u);
    EXPECT_DOUBLE_EQ(control.fraction(), 1.0);
}

TEST(RunControl, CancelIsSeenByEveryReader) {
    RunControl control;
    EXPECT_FALSE(control.cancelled());
    std::thread([&] { control.cancel(); }).join();
    EXPECT_TRUE(control.cancelled());
}

TEST(RunControl, PhaseNamesRoundTrip) {
    for (RunPhase p :
         {RunPhase::Queued, RunPhase::Tracing, RunPhase::PhotonMap, RunPhase::Rendering, RunPhase::Done}) {
        ASSERT_EQ(runPhaseNamed(runPhaseName(p)), p);
    }
    EXPECT_EQ(runPhaseName(RunPhase::PhotonMap), "photon_map");
    EXPECT_FALSE(runPhaseNamed("dancing"));
    EXPECT_FALSE(runPhaseNamed(""));
}

TEST(RunControl, TheProgressLineNamesTheRoundAndTheTimeLeft) {
    RunControl control;
    control.startPhase(RunPhase::Tracing, 1000);
    control.advance(50);
    EXPECT_EQ(cli::progressText(control, 3),
              "tracing [#                             ] 5%");  // too early to tell
    control.advance(200);
    EXPECT_EQ(cli::progressText(control, 10),
              "tracing [#######                       ] 25%, about 30 s left");
    control.startStage(2, 4, 25);
    for (int i = 0; i < 20; ++i) control.finishItem();
    EXPECT_EQ(cli::progressText(control, 720),
              "round 2 of 4: 20 of 25 points [########################      ] 80%, about 3 min left");
    control.startStage(3, 4, 1);
    EXPECT_EQ(cli::progressText(control, 1),
              "round 3 of 4: 0 of 1 point [                              ] 0%");
}
