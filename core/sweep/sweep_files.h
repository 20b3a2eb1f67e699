#pragma once
// What a sweep writes (docs/sweeps.md): sweep.json, sweep.csv and a point's JSON, which a resumed sweep and
// the ranks of a distributed one read back.
#include <string>

#include <nlohmann/json.hpp>

#include "sweep/sweep_run.h"

namespace facetlight {

// A point as sweep.json lists it: `at`, `values`, then `proportions`, `totals`, with the viewer on `viewer`,
// with fire enabled `fire` and with the colour view `colour`; or `error`.
nlohmann::json sweepPointJson(const SweepPlan& plan, const SweepPoint& point);
// The inverse, into a point of sweepPoints(plan) (its `stats`, which the JSON does not hold, stay empty).
// Throws Error when the JSON is not a point of this grid.
void restoreSweepPoint(const SweepPlan& plan, const nlohmann::json& j, SweepPoint& point);

// sweep.json's `axes`: each axis's name, unit, and values or choices.
nlohmann::json sweepAxesJson(const SweepPlan& plan);
// sweep.json (docs/sweeps.md; with the colour view its settings as `colour`) and sweep.csv (one row a point).
nlohmann::json sweepToJson(const SweepResult& result);
std::string sweepCsv(const SweepResult& result);

}  // namespace facetlight
