#pragma once
// A sweep as a job (docs/sweeps.md): the `sweep` object of the one job format (study_spec.h), read through
// its settings table, and its run into the files that the CLI writes and the service serves: sweep.json,
// sweep.csv, the pictures and, with a search for the best design, best.json and best.obj.
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "settings/settings_schema.h"
#include "study/sweep.h"

namespace facetlight {

struct SweepRequest {
    std::vector<SweepAxis> axes;
    CutValues set;  // parameters of the shape held at values other than their defaults
    std::vector<std::string> figures{"weighted_return"};  // drawn; a job names one (`figure`)
    std::string maximize;                                 // empty: no search for the best design
    std::vector<std::string> constraints;                 // "total_depth<=62", with `maximize`
    int refineRounds = 3;                                 // the search's finer grids after the sweep

    // The rounds the sweep runs: 1, or 1 + refineRounds with a search.
    int rounds() const { return maximize.empty() ? 1 : 1 + refineRounds; }
};

// The job's `sweep` object: {"axes": [{"name", "from", "to", "step"} | {"name", "values"} | {"name",
// "choices"}], "set": {...}, "figure", "maximize", "constraints": [...], "refine_rounds"}. Errors name the
// field by its dotted path ("sweep.axes[0].step").
const settings::Schema<SweepRequest>& sweepRequestSchema();
inline nlohmann::json toJson(const SweepRequest& r) {
    return sweepRequestSchema().write(r);
}

// The sweep of `shape` the request asks for, with every point's trace settings; checked, throwing Error
// naming the field ("mesh" for a shape the cut library lacks, "sweep.axes[1]", "sweep.set", ...).
SweepSpec sweepSpec(const std::string& shape, const SweepRequest& request, const TraceSettings& trace);

// What a request's figures are called in its errors: the job's fields, or the CLI's options.
struct SweepFigureFields {
    std::string figure = "sweep.figure", maximize = "sweep.maximize", constraints = "sweep.constraints";
    bool indexed = true;  // constraints[i]
};
// Throws Error naming the field when a figure the request draws, maximizes or constrains is not one, or is a
// fire figure and `trace` does not enable fire.
void checkSweepFigures(const SweepRequest& request, const TraceSettings& trace,
                       const SweepFigureFields& fields = {});

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

    std::string json() const { return sweepToJson(sweep).dump(2) + "\n"; }
    std::string csv() const { return sweepCsv(sweep); }
};

// Runs the sweep (and the search) on every rank of `comm`; rank 0 returns the outputs, the others only
// `sweep`. Round r is stage r + 1 of request.rounds() in control (control.stage(), itemsDone()). Throws
// Error when no point could be traced, Canceled when control.cancel() stops it.
SweepOutputs runSweepRequest(const SweepSpec& spec, const SweepRequest& request, RunControl& control,
                             Communicator& comm, const SweepCheckpoint& checkpoint = {});

}  // namespace facetlight
