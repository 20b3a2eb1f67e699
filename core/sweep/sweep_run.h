#pragma once
// Tracing a sweep's points: each design's stone is built once and shared by the points that use it, several
// points are traced at once, and an interrupted sweep resumes from the points it kept.
#include <cstddef>
#include <functional>
#include <optional>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_plan.h"
#include "util/distributed.h"
#include "util/run_control.h"

namespace facetlight {

struct SweepResult {
    SweepPlan plan;
    std::vector<SweepPoint> points;
    double seconds = 0;
};

// What a sweep's points take from, and give to, outside: points finished before (an interrupted sweep
// resumes from them), and each point as it finishes.
struct SweepPointHooks {
    // A point's sweepPointJson if it was finished before; asked on rank 0 before any tracing.
    std::function<std::optional<nlohmann::json>(size_t point)> restore;
    // Each point traced on this rank as it finishes (from the worker that traced it) and, on rank 0, every
    // other rank's points once they are gathered. Not called for restored points.
    std::function<void(size_t point, const SweepPoint&)> onPoint;
};

// Builds each design once, then traces the points on plan.trace.threads workers (several points at once, the
// threads left over shared within each point), reporting to `control` in photons over all points
// (RunPhase::Tracing, then Done) and in points (control.finishItem). Throws Canceled when control.cancel()
// stops it, Error on a bad plan.
SweepResult runSweep(const SweepPlan& plan, RunControl& control, const SweepPointHooks& hooks = {});
// The same on every rank of `comm`: rank r traces the points k with k mod size = r, and every rank returns
// every point, bit for bit those of a single process (the gathered points travel as their JSON, whose numbers
// read back exactly). Restored points come from rank 0.
SweepResult runSweep(const SweepPlan& plan, RunControl& control, const SweepPointHooks& hooks,
                     Communicator& comm);

}  // namespace facetlight
