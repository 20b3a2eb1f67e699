#pragma once
// The figures of merit a sweep reports for a point and draws, searches or constrains.
#include <string>
#include <vector>

#include "trace/trace_settings.h"

namespace facetlight {

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

}  // namespace facetlight
