#include "sweep/sweep_figures.h"

#include <algorithm>

#include "util/error.h"

namespace facetlight {
namespace {

// The figures of the statistics' `totals`.
const std::vector<std::string>& sweepPlainFigureNames() {
    static const std::vector<std::string> names{"crown_return",    "crown_return_with_reflection",
                                                "weighted_return", "cone_return_30",
                                                "cone_return_45",  "cone_return_60",
                                                "leakage"};
    return names;
}

}  // namespace

const std::vector<std::string>& sweepFigureNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all = sweepPlainFigureNames();
        all.insert(all.end(), sweepFireFigureNames().begin(), sweepFireFigureNames().end());
        return all;
    }();
    return names;
}

const std::vector<std::string>& sweepFireFigureNames() {
    static const std::vector<std::string> names{"mean_separation_deg", "coloured_share",
                                                "coloured_return_weighted", "pair_share", "split_share"};
    return names;
}

std::vector<std::string> sweepFigureNames(const TraceSettings& trace) {
    std::vector<std::string> names = sweepPlainFigureNames();
    if (trace.fire.enabled)
        names.insert(names.end(), sweepFireFigureNames().begin(), sweepFireFigureNames().end());
    return names;
}

void checkSweepFigure(const std::string& name, const TraceSettings& trace) {
    const auto& names = sweepFigureNames();
    if (std::find(names.begin(), names.end(), name) == names.end()) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        throw Error("unknown figure '" + name + "'; the figures are: " + list);
    }
    const auto& fire = sweepFireFigureNames();
    if (!trace.fire.enabled && std::find(fire.begin(), fire.end(), name) != fire.end())
        throw Error(
            "the figure " + name +
            " is measured by a fire trace, which is off: turn it on (--fire, or a job's fire.enabled)");
}

std::string sweepFigureUnit(const std::string& name) {
    return name == "mean_separation_deg" ? "deg" : "";
}
}  // namespace facetlight
