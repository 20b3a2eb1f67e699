#pragma once
// The figures of merit a sweep reports for a point and draws, searches or constrains.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "trace/trace_settings.h"
#include "viewer/colour_view.h"

namespace facetlight {

// The figures of merit a sweep can report for a point, each with a `_stderr`: the viewer figures and the
// light-performance score (keys of the statistics' `viewer.figures`, and `score`), which a sweep reports
// unless the viewer is off; keys of the statistics' `totals`; the fire figures (keys of the statistics'
// `fire`), which only a sweep that traces fire reports; then the colour figures (the statistics' `colour`),
// which only a sweep with the colour view reports.
const std::vector<std::string>& sweepFigureNames();
const std::vector<std::string>& sweepViewerFigureNames();
const std::vector<std::string>& sweepFireFigureNames();
const std::vector<std::string>& sweepColourFigureNames();
// The figure a sweep draws and searches unless told otherwise: brightness, or with the viewer off the
// cosine-weighted return.
inline constexpr const char* kDefaultSweepFigure = "brightness";
inline constexpr const char* kDefaultSweepFigureWithoutViewer = "weighted_return";
inline std::string defaultSweepFigure(const TraceSettings& trace) {
    return trace.viewer.enabled ? kDefaultSweepFigure : kDefaultSweepFigureWithoutViewer;
}
// The figures a sweep with these trace settings reports: the viewer figures only when the viewer is on, the
// fire figures only when fire is enabled, the colour figures only with the colour view (`colour`).
std::vector<std::string> sweepFigureNames(const TraceSettings& trace, bool colour);
// Throws Error listing the figures when `name` is not one, or saying how to turn the viewer, fire or the
// colour view on when it is one of their figures and they are off.
void checkSweepFigure(const std::string& name, const TraceSettings& trace, bool colour);
// A figure's unit: "deg" for an angle, "CIELAB" for a colour coordinate (L*, a*, b*, C*ab), "" for a share
// (of the photons hitting the stone, or of the face-up area).
std::string sweepFigureUnit(const std::string& name);
// A point's colour figures from its colour view, each with its `_stderr`: the means over the face-up area of
// L*, a*, b* and C*ab, and the windowed, extinct and saturated shares (viewer/colour_view.h).
nlohmann::json sweepColourFigures(const ColourView& view);

}  // namespace facetlight
