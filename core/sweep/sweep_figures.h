#pragma once
// The figures of merit a sweep reports for a point and draws, searches or constrains.
#include <string>
#include <vector>

#include "trace/trace_settings.h"

namespace facetlight {

// The figures of merit a sweep can report for a point, each with a `_stderr`: the viewer figures and the
// light-performance score (keys of the statistics' `viewer.figures`, and `score`), which a sweep reports
// unless the viewer is off; keys of the statistics' `totals`; then the fire figures (keys of the statistics'
// `fire`), which only a sweep that traces fire reports.
const std::vector<std::string>& sweepFigureNames();
const std::vector<std::string>& sweepViewerFigureNames();
const std::vector<std::string>& sweepFireFigureNames();
// The figure a sweep draws and searches unless told otherwise: brightness, or with the viewer off the
// cosine-weighted return.
inline constexpr const char* kDefaultSweepFigure = "brightness";
inline constexpr const char* kDefaultSweepFigureWithoutViewer = "weighted_return";
inline std::string defaultSweepFigure(const TraceSettings& trace) {
    return trace.viewer.enabled ? kDefaultSweepFigure : kDefaultSweepFigureWithoutViewer;
}
// The figures a sweep with these trace settings reports: the viewer figures only when the viewer is on, the
// fire figures only when fire is enabled.
std::vector<std::string> sweepFigureNames(const TraceSettings& trace);
// Throws Error listing the figures when `name` is not one, or saying how to turn the viewer or fire on when
// it is a viewer or fire figure and `trace` turns it off.
void checkSweepFigure(const std::string& name, const TraceSettings& trace);
// A figure's unit: "deg" for an angle, "" for a share of the photons hitting the stone.
std::string sweepFigureUnit(const std::string& name);

}  // namespace facetlight
