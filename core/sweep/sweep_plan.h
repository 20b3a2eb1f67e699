#pragma once
// A sweep: one shape of the cut library traced over a grid of one or two of its parameters (or of trace
// settings: tilt, head shadow, material, light, n, size). Every point is an ordinary trace with the sweep's
// seed, so neighbouring points share their random numbers (docs/sweeps.md) and a point equals a single trace
// of the same design bit for bit.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cuts/cut_library.h"
#include "cuts/design_shape.h"
#include "stats/facet_stats.h"
#include "sweep/sweep_axis.h"
#include "trace/trace_settings.h"
#include "viewer/colour_view.h"

namespace facetlight {

// A sweep resolved into what runs: the shape, every parameter held, the axes and every point's trace
// settings, checked by validate(). planSweep makes it from a SweepRequest (what the user asked for); the
// tests and benchmarks build one directly.
struct SweepPlan {
    std::string shape;  // a shape of the cut library, or the name of `file`'s
    std::shared_ptr<const FileShape> file;  // a design or mesh file swept instead of a library shape
    CutValues fixed;  // the shape's other parameters; defaults for those not given
    std::vector<SweepAxis> axes;
    TraceSettings trace;  // every point's settings; `threads` is the whole sweep's worker count
    // With the colour view: every point's face-up colour (a job's `colour`), for the colour figures.
    std::optional<ColourSettings> colour;

    // Throws Error naming the fault: an unknown shape, parameter or axis, an axis given twice, a value
    // outside its parameter's range, no axis or more than kMaxSweepAxes, more than kMaxSweepPoints points, an
    // optic axis turned in a stone that is not uniaxial and polarised.
    void validate() const;
    // The shape swept: `file`'s, else the library's shape of that name.
    const CutShape& cutShape() const { return file ? file->shape : findCutShape(shape); }
    size_t pointCount() const;
    // The unit of an axis: the parameter's ("deg", "%", ""), "deg" for tilt, head shadow and the optic axis,
    // "mm" for size.
    std::string unit(const SweepAxis& axis) const;

  private:
    void checkOpticAxisSweep(const std::string& name) const;
};

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
    // With the viewer on, the viewer figures and the score, each with its `_stderr`.
    nlohmann::json viewer;
    nlohmann::json colour;  // with the colour view, the colour figures (sweepColourFigures)

    bool ok() const { return error.empty(); }
    double figure(const std::string& name) const { return figures(name).at(name).get<double>(); }
    double stderrOf(const std::string& name) const {
        return figures(name).at(name + "_stderr").get<double>();
    }
    // The member holding `name`: `totals`, `viewer` for a viewer figure, `colour` for a colour figure, or
    // `fire` for a fire figure.
    const nlohmann::json& figures(const std::string& name) const {
        return totals.contains(name)   ? totals
               : viewer.contains(name) ? viewer
               : colour.contains(name) ? colour
                                       : fire;
    }
};

// Every point of the grid with its design and settings, none traced: the first axis varies slowest.
std::vector<SweepPoint> sweepPoints(const SweepPlan& plan);

}  // namespace facetlight
