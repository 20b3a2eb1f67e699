#pragma once
// A sweep's axis: one varied quantity and its values, as the CLI's --vary text or a job's range gives them.
#include <cstddef>
#include <string>
#include <vector>

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
// clang-format off
inline const std::vector<std::string> kTraceAxes{
    "tilt", "head_shadow", "material", "light", "n", "size_mm",
    "optic_axis_tilt", "optic_axis_azimuth", "optic_axis_rotation"};
// clang-format on
constexpr size_t kMaxSweepPoints = 10000;
constexpr size_t kMaxSweepAxes = 2;

// Whether `name` is one of kTraceAxes; whether it is one of those that take names (material, light).
bool isTraceAxis(const std::string& name);
bool isChoiceAxis(const std::string& name);

// "pavilion=37:45:0.25" (lo:hi:step, both ends included), "pavilion=39,40.5,42" or "material=diamond,
// cubic_zirconia". Throws Error for malformed text, an empty or inverted range, a step of 0 or below, or more
// than kMaxSweepPoints values.
SweepAxis parseSweepAxis(const std::string& text);
// lo, lo + step, ... up to hi (both ends included); throws Error as parseSweepAxis does.
SweepAxis sweepRange(const std::string& name, double lo, double hi, double step);

}  // namespace facetlight
