#pragma once
// A sweep: one shape of the cut library traced over a grid of one or two of its parameters (or of trace
// settings: tilt, head shadow, material, light). Every point is an ordinary trace with the sweep's seed, so
// neighbouring points share their random numbers (docs/sweeps.md) and a point equals a single trace of the
// same design bit for bit. Each design's stone is built once and shared by the points that use it.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cuts/cut_library.h"
#include "stats/facet_stats.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/distributed.h"
#include "util/run_control.h"

namespace facetlight {

// One varied quantity: a parameter of the shape, or one of the trace settings kTraceAxes names. Numeric axes
// hold `values`; the material and light axes hold `choices` (names) instead.
struct SweepAxis {
    std::string name;
    std::vector<double> values;
    std::vector<std::string> choices;

    size_t size() const { return choices.empty() ? values.size() : choices.size(); }
    bool numeric() const { return choices.empty(); }
    // The value's text as the CSV and the pictures write it.
    std::string label(size_t i) const;
};

// The trace settings a sweep may vary, besides the shape's parameters.
inline const std::vector<std::string> kTraceAxes{"tilt", "head_shadow", "material", "light"};
constexpr size_t kMaxSweepPoints = 10000;
constexpr size_t kMaxSweepAxes = 2;

// "pavilion=37:45:0.25" (lo:hi:step, both ends included), "pavilion=39,40.5,42" or "material=diamond,
// cubic_zirconia". Throws Error for malformed text, an empty or inverted range, a step of 0 or below, or more
// than kMaxSweepPoints values.
SweepAxis parseSweepAxis(const std::string& text);
// lo, lo + step, ... up to hi (both ends included); throws Error as parseSweepAxis does.
SweepAxis sweepRange(const std::string& name, double lo, double hi, double step);

struct SweepSpec {
    std::string shape;
    CutValues fixed;  // the shape's other parameters; defaults for those not given
    std::vector<SweepAxis> axes;
    TraceSettings trace;  // every point's settings; `threads` is the whole sweep's worker count

    // Throws Error naming the fault: an unknown shape, parameter or axis, an axis given twice, a value
    // outside its parameter's range, no axis or more than kMaxSweepAxes, more than kMaxSweepPoints points.
    void validate() const;
    size_t pointCount() const;
    // The unit of an axis: the parameter's ("deg", "%", ""), "deg" for tilt and head shadow.
    std::string unit(const SweepAxis& axis) const;
};

// The figures of merit a sweep can report for a point, each with a `_stderr`: keys of the statistics'
// `totals`, then the fire figures (keys of the statistics' `fire`), which only a sweep that traces fire
// reports.
const std::vector<std::string>& sweepFigureNames();
const std::vector<std::string>& sweepFireFigureNames();
// The figures a sweep with these trace settings reports: the fire figures only when fire is enabled.
std::vector<std::string> sweepFigureNames(const TraceSettings& trace);
// Throws Error listing the figures when `name` is not one, or saying how to turn fire on when it is a fire
// figure and `trace` does not enable fire.
void checkSweepFigure(const std::string& name, const TraceSettings& trace);
// A figure's unit: "deg" for an angle, "" for a share of the photons hitting the stone.
std::string sweepFigureUnit(const std::string& name);

// One point of the grid: its position on each axis, the design and settings traced there, and what came out.
struct SweepPoint {
    std::vector<size_t> at;  // index along each axis
    CutValues cut;           // every parameter of the shape
    TraceSettings trace;
    std::string error;  // why this point could not be traced (proportions that cannot make the stone)
    FacetStats stats;
    nlohmann::json proportions;  // the stone's trade proportions, as the statistics' `mesh.proportions`
    nlohmann::json totals;       // the statistics' `totals`: counts, figures and their standard errors
    nlohmann::json fire;  // with fire enabled, the fire figures of the statistics' `fire` and their errors

    bool ok() const { return error.empty(); }
    double figure(const std::string& name) const { return figures(name).at(name).get<double>(); }
    double stderrOf(const std::string& name) const {
        return figures(name).at(name + "_stderr").get<double>();
    }
    // The member holding `name`: `totals`, or `fire` for a fire figure.
    const nlohmann::json& figures(const std::string& name) const {
        return totals.contains(name) ? totals : fire;
    }
};

// Every point of the grid with its design and settings, none traced: the first axis varies slowest.
std::vector<SweepPoint> sweepPoints(const SweepSpec& spec);

struct SweepResult {
    SweepSpec spec;
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

// Builds each design once, then traces the points on spec.trace.threads workers (several points at once, the
// threads left over shared within each point), reporting to `control` in photons over all points
// (RunPhase::Tracing, then Done) and in points (control.finishItem). Throws Canceled when control.cancel()
// stops it, Error on a bad spec.
SweepResult runSweep(const SweepSpec& spec, RunControl& control, const SweepPointHooks& hooks = {});
// The same on every rank of `comm`: rank r traces the points k with k mod size = r, and every rank returns
// every point, bit for bit those of a single process (the gathered points travel as their JSON, whose numbers
// read back exactly). Restored points come from rank 0.
SweepResult runSweep(const SweepSpec& spec, RunControl& control, const SweepPointHooks& hooks,
                     Communicator& comm);

// A point as sweep.json lists it: `at`, `values`, then `proportions`, `totals` and, with fire enabled,
// `fire`; or `error`.
nlohmann::json sweepPointJson(const SweepSpec& spec, const SweepPoint& point);
// The inverse, into a point of sweepPoints(spec) (its `stats`, which the JSON does not hold, stay empty).
// Throws Error when the JSON is not a point of this grid.
void restoreSweepPoint(const nlohmann::json& j, SweepPoint& point);

// sweep.json's `axes`: each axis's name, unit, and values or choices.
nlohmann::json sweepAxesJson(const SweepSpec& spec);
// sweep.json (docs/sweeps.md) and sweep.csv (one row a point).
nlohmann::json sweepToJson(const SweepResult& result);
std::string sweepCsv(const SweepResult& result);

}  // namespace facetlight
