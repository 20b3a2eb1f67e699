#pragma once
// Where a job stands, for whoever shows it (the service's job status). Its steps come from its settings as
// the study runs them: the phases with work (studyUnits: tracing, then with pictures the photon map and the
// rendering), or a sweep's rounds (one, or a search's). `step` of `steps` and `overall` say where the whole
// job is, so that clients need not know the phases.
#include <cstdint>
#include <string>

#include "study/study.h"
#include "util/run_control.h"

namespace facetlight {

struct JobProgress {
    std::string phase;  // the run's (runPhaseName, "starting" before the first), or the job's state
    uint64_t done = 0, total = 0;  // units of that phase, this process's share (photons, pixels)
    double fraction = 0;           // done / total, 0 without a total
    int step = 0;                  // the step under way, from 1; 0 before the first
    int steps = 1;
    double overall = 0;  // through the whole job, 0 to 1
    bool sweep = false;  // then the points: whole points of the round under way, or of the grid
    uint64_t pointsDone = 0, pointsTotal = 0;
};

// A job not under way (queued, or ended short of its results: `phase` names why): nothing done.
JobProgress idleProgress(const StudySettings& settings, std::string phase);
// A job whose results are all there.
JobProgress finishedProgress(const StudySettings& settings);
// A job under way, from the control its run reports to.
JobProgress runningProgress(const StudySettings& settings, const RunControl& control);

}  // namespace facetlight
