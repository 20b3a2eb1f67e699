#pragma once
// A sweep as a job asks for it (docs/sweeps.md): the `sweep` object of the one job format
// (study/job_request.h), read through its settings table, and the checked plan made from it.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sweep/sweep_figures.h"
#include "sweep/sweep_plan.h"
#include "settings/settings_schema.h"

namespace facetlight {

// A sweep as its user asked for it (the job's `sweep` object, `SweepRequest` in server/openapi.json, or the
// CLI's options): the axes, the parameters held, the figures and the search. It names no shape and holds no
// trace settings; planSweep resolves it with the job's into the SweepPlan that runs.
struct SweepRequest {
    std::vector<SweepAxis> axes;
    CutValues set;  // parameters of the shape held at values other than their defaults
    std::vector<std::string> figures{kDefaultSweepFigure};  // drawn; a job names one (`figure`)
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

// The plan of the sweep of `shape` the request asks for, with every point's trace settings and, with
// `colour` (the job's colour view), every point's colour figures; checked, throwing Error naming the field
// ("mesh" for a shape the cut library lacks, "sweep.axes[1]", "sweep.set", "material" for a colour view with
// no absorbing point, ...).
SweepPlan planSweep(const std::string& shape, const SweepRequest& request, const TraceSettings& trace,
                    const std::optional<ColourSettings>& colour);
// The same for a design or mesh file (cuts/design_shape.h): a GemCad design's tiers are its parameters.
SweepPlan planSweep(std::shared_ptr<const FileShape> file, const SweepRequest& request,
                    const TraceSettings& trace, const std::optional<ColourSettings>& colour);
// A shape of the cut library by name, else a design or mesh file by path (trusted callers only: the CLI, and
// the service once its catalog has turned a job's mesh into a path). Errors name the field as planSweep's.
SweepPlan planSweepOf(const std::string& shapeOrPath, const SweepRequest& request, const TraceSettings& trace,
                      const std::optional<ColourSettings>& colour);
bool isLibraryShape(const std::string& name);

// What a request's figures are called in its errors: the job's fields, or the CLI's options.
struct SweepFigureFields {
    std::string figure = "sweep.figure", maximize = "sweep.maximize", constraints = "sweep.constraints";
    bool indexed = true;  // constraints[i]
};
// Throws Error naming the field when a figure the request draws, maximizes or constrains is not one, or is a
// viewer, fire or colour figure and `trace` turns the viewer or fire off or there is no colour view
// (`colour`).
void checkSweepFigures(const SweepRequest& request, const TraceSettings& trace, bool colour,
                       const SweepFigureFields& fields = {});

}  // namespace facetlight
