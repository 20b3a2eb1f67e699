#include "study/job_progress.h"

#include <gtest/gtest.h>

using namespace facetlight;

namespace {

StudySettings rendered() {
    StudySettings s;
    s.render = RenderSettings{};
    return s;
}

StudySettings sweepOf(std::vector<size_t> sizes, std::string maximize = {}) {
    StudySettings s;
    s.sweep = SweepRequest{};
    for (const size_t n : sizes) s.sweep->axes.push_back({"pavilion", std::vector<double>(n, 40.0), {}});
    s.sweep->maximize = std::move(maximize);
    s.sweep->refineRounds = 2;
    return s;
}

TEST(JobProgress, StepsAreThePhasesWithWorkOrTheSweepsRounds) {
    // A trace, then the viewer's office figures; a render adds its photon map and picture.
    EXPECT_EQ(idleProgress(StudySettings{}, "queued").steps, 2);
    EXPECT_EQ(idleProgress(rendered(), "queued").steps, 4);
    EXPECT_EQ(idleProgress(sweepOf({4, 3}), "queued").steps, 1);
    EXPECT_EQ(idleProgress(sweepOf({4}, "weighted_return"), "queued").steps, 3);
    const JobProgress queued = idleProgress(sweepOf({4, 3}), "queued");
    EXPECT_EQ(queued.phase, "queued");
    EXPECT_TRUE(queued.sweep);
    EXPECT_EQ(queued.pointsTotal, 12u);
    EXPECT_EQ(queued.pointsDone, 0u);
    EXPECT_EQ(queued.step, 0);
    EXPECT_FALSE(idleProgress(rendered(), "failed").sweep);
}

TEST(JobProgress, FinishedIsEveryStepDone) {
    const JobProgress p = finishedProgress(sweepOf({5}));
    EXPECT_EQ(p.phase, "done");
    EXPECT_EQ(p.step, p.steps);
    EXPECT_EQ(p.overall, 1.0);
    EXPECT_EQ(p.fraction, 1.0);
    EXPECT_EQ(p.pointsDone, 5u);
}

TEST(JobProgress, AStudyUnderWayIsAtItsPhasesShare) {
    RunControl control;
    EXPECT_EQ(runningProgress(rendered(), control).phase, "starting");
    control.show(RunPhase::PhotonMap, 1, 4);
    const JobProgress p = runningProgress(rendered(), control);
    EXPECT_EQ(p.phase, "photon_map");
    EXPECT_EQ(p.step, 3);
    EXPECT_EQ(p.fraction, 0.25);
    EXPECT_DOUBLE_EQ(p.overall, 2.25 / 4);
    control.show(RunPhase::Done, 0, 0);
    EXPECT_EQ(runningProgress(rendered(), control).overall, 1.0);
    EXPECT_EQ(runningProgress(rendered(), control).step, 4);
}

TEST(JobProgress, ASweepUnderWayCountsTheRoundsPoints) {
    RunControl control;
    const StudySettings search = sweepOf({4}, "weighted_return");
    control.show(RunPhase::Tracing, 50, 100);  // a launcher's child: photons only, no rounds
    EXPECT_DOUBLE_EQ(runningProgress(search, control).overall, 0.5 / 3);
    EXPECT_EQ(runningProgress(search, control).step, 0);
    control.startStage(2, 3, 8);
    for (int i = 0; i < 2; ++i) control.finishItem();
    const JobProgress p = runningProgress(search, control);
    EXPECT_EQ(p.step, 2);
    EXPECT_EQ(p.pointsDone, 2u);
    EXPECT_EQ(p.pointsTotal, 8u);
    EXPECT_DOUBLE_EQ(p.overall, 1.25 / 3);
}

// Each round ends its sweep with the Done phase; only the last round's is the end of the search (issue 30:
// the overall share went 0.6, 1.0, then 0.783 when the last round started).
TEST(JobProgress, ARoundsEndIsNotTheSearchsEnd) {
    RunControl control;
    const StudySettings search = sweepOf({4}, "weighted_return");
    control.startStage(2, 3, 8);
    for (int i = 0; i < 8; ++i) control.finishItem();
    control.startPhase(RunPhase::Done, 0);
    EXPECT_DOUBLE_EQ(runningProgress(search, control).overall, 2.0 / 3);
    control.startStage(3, 3, 8);
    EXPECT_DOUBLE_EQ(runningProgress(search, control).overall, 2.0 / 3);
    for (int i = 0; i < 8; ++i) control.finishItem();
    control.startPhase(RunPhase::Done, 0);
    EXPECT_DOUBLE_EQ(runningProgress(search, control).overall, 1.0);
}

}  // namespace
