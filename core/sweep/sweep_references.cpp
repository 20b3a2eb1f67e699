#include "sweep/sweep_references.h"

#include <utility>

#include "cuts/cut_library.h"

namespace facetlight {

std::vector<SweepReference> sweepReferences(const SweepPlan& plan) {
    std::vector<SweepReference> out;
    for (const auto& [shape, label] : {std::pair{"round_brilliant", "GIA reference"},
                                       std::pair{"round_brilliant_tolkowsky", "Tolkowsky 1919"}}) {
        const CutValues values = completeCutValues(findCutShape(shape), {});
        SweepReference reference{shape, label, {}};
        for (const SweepAxis& axis : plan.axes) {
            if (!values.count(axis.name)) break;  // a trace setting (tilt, material, ...) or not theirs
            reference.values.push_back(values.at(axis.name));
        }
        if (!plan.axes.empty() && reference.values.size() == plan.axes.size())
            out.push_back(std::move(reference));
    }
    return out;
}

}  // namespace facetlight
