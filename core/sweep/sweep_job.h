#pragma once
// A sweep job's run (docs/sweeps.md): the sweep and, with a search for the best design, its finer rounds,
// into the files that the CLI writes and the service serves: sweep.json, sweep.csv, the pictures and, with a
// search, best.json, best.obj and best.asc.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/run_control.h"
#include "sweep/sweep_files.h"
#include "sweep/sweep_request.h"

namespace facetlight {

// Where an interrupted sweep's finished points are kept (the service: files in the job's folder): `restore`
// gives a point of a round (sweepPointJson) if it was finished before, `store` keeps one as it finishes
// (called from the worker threads, for distinct points at once).
struct SweepCheckpoint {
    std::function<std::optional<nlohmann::json>(size_t round, size_t point)> restore;
    std::function<void(size_t round, size_t point, const nlohmann::json&)> store;
};

struct SweepOutputs {
    SweepResult sweep;                                          // the grid asked for (a search's first round)
    std::vector<std::pair<std::string, std::string>> pictures;  // file name and PNG, one per figure
    nlohmann::json best;                                        // best.json; null without a search
    std::string bestObj;                                        // the best design, with a search
    std::string bestAsc;  // and as a GemCad design (empty for a mesh that is not convex)

    std::string json() const { return sweepToJson(sweep).dump(2) + "\n"; }
    std::string csv() const { return sweepCsv(sweep); }
};

// Runs the sweep (and the search) on every rank of `comm`; rank 0 returns the outputs, the others only
// `sweep`. Round r is stage r + 1 of request.rounds() in control (control.stage(), itemsDone()). Throws
// Error when no point could be traced, Canceled when control.cancel() stops it.
SweepOutputs runSweepRequest(const SweepPlan& plan, const SweepRequest& request, RunControl& control,
                             Communicator& comm, const SweepCheckpoint& checkpoint = {});

}  // namespace facetlight
