#include "study/job_progress.h"

#include <algorithm>
#include <vector>

namespace facetlight {
namespace {

// The phases of a study with work to do, in the order runStudy runs them.
std::vector<RunPhase> studyPhases(const StudySettings& settings) {
    std::vector<RunPhase> phases;
    for (const RunPhase phase : {RunPhase::Tracing, RunPhase::Viewing, RunPhase::PhotonMap, RunPhase::Rendering})
        if (studyUnits(settings, phase) > 0) phases.push_back(phase);
    return phases;
}

}  // namespace

JobProgress idleProgress(const StudySettings& settings, std::string phase) {
    JobProgress p;
    p.phase = std::move(phase);
    p.sweep = settings.sweep.has_value();
    if (p.sweep) {
        p.steps = settings.sweep->rounds();
        p.pointsTotal = 1;
        for (const SweepAxis& axis : settings.sweep->axes) p.pointsTotal *= axis.size();
    } else {
        p.steps = int(studyPhases(settings).size());
    }
    return p;
}

JobProgress finishedProgress(const StudySettings& settings) {
    JobProgress p = idleProgress(settings, "done");
    p.done = p.total = 1;
    p.fraction = 1;
    p.step = p.steps;
    p.overall = 1;
    p.pointsDone = p.pointsTotal;
    return p;
}

JobProgress runningProgress(const StudySettings& settings, const RunControl& control) {
    const RunPhase phase = control.phase();
    JobProgress p =
        idleProgress(settings, phase == RunPhase::Queued ? "starting" : std::string(runPhaseName(phase)));
    p.done = control.done();
    p.total = control.total();
    p.fraction = p.total ? double(p.done) / double(p.total) : 0.0;
    const double within = std::clamp(p.fraction, 0.0, 1.0);
    if (p.sweep && control.stage() > 0) {
        // Whole points of the round under way (pointsTotal: that round's).
        p.step = control.stage();
        p.pointsDone = control.itemsDone();
        p.pointsTotal = control.itemsTotal();
        p.overall =
            (p.step - 1 + (p.pointsTotal ? double(p.pointsDone) / double(p.pointsTotal) : 0.0)) / p.steps;
    } else if (p.sweep) {  // in a launcher's child: its photons only
        p.overall = within / p.steps;
    } else {
        const std::vector<RunPhase> phases = studyPhases(settings);
        for (int i = 0; i < int(phases.size()); ++i) {
            if (phases[i] != phase) continue;
            p.step = i + 1;
            p.overall = (i + within) / p.steps;
        }
    }
    // The work is over, its results are being written. A sweep's rounds each end so, and their points say
    // where it is: the search is not over when a round is.
    if (phase == RunPhase::Done && !(p.sweep && control.stage() > 0)) {
        p.step = p.steps;
        p.overall = 1;
    }
    return p;
}

}  // namespace facetlight
