#pragma once
// The shipped reference designs a sweep's map rings (GIA reference, Tolkowsky 1919): where they lie on the
// sweep's axes. The CLI's map and the service's points answer take them from here, so both mark the same.
#include <string>
#include <vector>

#include "sweep/sweep_plan.h"

namespace facetlight {

struct SweepReference {
    std::string shape;           // the cut library's shape ("round_brilliant_tolkowsky")
    std::string label;           // as the pictures write it ("Tolkowsky 1919")
    std::vector<double> values;  // the design's value on each of the plan's axes, in their order
};

// The reference designs that have every axis of `plan` as a parameter (none when an axis is a trace
// setting), with their default values on those axes.
std::vector<SweepReference> sweepReferences(const SweepPlan& plan);

}  // namespace facetlight
