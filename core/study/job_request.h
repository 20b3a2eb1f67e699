#pragma once
// The one job format: what `POST /api/jobs` takes, what the service stores and hands its launcher's child,
// and what `facetlight study --job` reads. The trace settings sit at the top level beside `mesh`:
//   {"mesh": "round_brilliant", "name": "...", "photons": 1e6, ..., "light": {...}, "render": false | true |
//   {...}}
#include <string>

#include <nlohmann/json.hpp>

#include "study/study.h"

namespace facetlight {

// A job as its user asked for it (`JobRequest` in server/openapi.json): the mesh by name, the settings, and
// for a sweep its SweepRequest in `settings.sweep`, still unresolved; a sweep's SweepPlan is made from it
// (planSweep) when the job runs.
struct JobRequest {
    std::string mesh;  // a file, a shipped shape's name, or (in the service) an uploaded mesh's id
    std::string name;  // the stone's name in the results; empty: the one the mesh gives
    StudySettings settings;
    CutValues cut;  // a cut library shape's parameters other than their defaults (a sweep's point)

    // Read through the settings schema onto `defaults` (keys absent keep their values); throws Error naming
    // the field by its dotted path.
    static JobRequest fromJson(const nlohmann::json& j, JobRequest defaults = {});
};

// The stone a spec with `cut` names: its shape built with those parameters. `source` is where the shape is:
// the spec's mesh for a shape of the cut library, else the path of its GemCad design (the service's catalog
// finds it; `cut` then holds tier slopes, tier:NAME, docs/gemcad.md).
Stone cutStone(const JobRequest& spec, const std::string& source);

// The name of a job that gives none: its design (`design`: "round brilliant", an upload's file name), the cut
// parameters it changes from the shape's defaults as cutters write them ("round brilliant P 43.5"), and for a
// sweep what it varies ("round brilliant, sweep of pavilion × crown"): the job list tells designs apart by
// it.
std::string defaultJobName(const JobRequest& spec, const std::string& design);

// Every setting written out, so a stored job runs the same after a restart even if defaults change.
nlohmann::json toJson(const JobRequest& spec);

}  // namespace facetlight
