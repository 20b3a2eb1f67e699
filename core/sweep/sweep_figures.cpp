#include "sweep/sweep_figures.h"

#include <algorithm>

#include "util/error.h"
#include "viewer/viewer_figures.h"

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
        std::vector<std::string> all = sweepViewerFigureNames();
        all.insert(all.end(), sweepPlainFigureNames().begin(), sweepPlainFigureNames().end());
        all.insert(all.end(), sweepFireFigureNames().begin(), sweepFireFigureNames().end());
        return all;
    }();
    return names;
}

const std::vector<std::string>& sweepViewerFigureNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const ViewerFigureInfo& f : kViewerFigures) all.emplace_back(f.key);
        all.emplace_back("score");
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
    std::vector<std::string> names;
    if (trace.viewer.enabled) names = sweepViewerFigureNames();
    names.insert(names.end(), sweepPlainFigureNames().begin(), sweepPlainFigureNames().end());
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
    const auto& viewer = sweepViewerFigureNames();
    if (!trace.viewer.enabled && std::find(viewer.begin(), viewer.end(), name) != viewer.end())
        throw Error("the figure " + name +
                    " is a viewer figure, and the viewer is off: turn it on (drop --no-view, or a job's "
                    "viewer.enabled false)");
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
