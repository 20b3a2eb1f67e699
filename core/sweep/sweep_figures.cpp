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

// The colour figures, each from its place in the colour view: a mean over the face-up area with the mean's
// error, or a share with its binomial error.
struct ColourFigureRow {
    const char* key;
    const ColourFigure ColourView::*figure;  // null for a share
    const ColourShare ColourView::*share;
};
constexpr ColourFigureRow kColourFigures[] = {
    {"colour_lightness", &ColourView::L, nullptr},
    {"colour_a", &ColourView::a, nullptr},
    {"colour_b", &ColourView::b, nullptr},
    {"colour_chroma", &ColourView::chroma, nullptr},
    {"colour_windowed", nullptr, &ColourView::windowed},
    {"colour_extinct", nullptr, &ColourView::extinct},
    {"colour_saturated", nullptr, &ColourView::saturated},
};

bool contains(const std::vector<std::string>& names, const std::string& name) {
    return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

const std::vector<std::string>& sweepFigureNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all = sweepViewerFigureNames();
        all.insert(all.end(), sweepPlainFigureNames().begin(), sweepPlainFigureNames().end());
        all.insert(all.end(), sweepFireFigureNames().begin(), sweepFireFigureNames().end());
        all.insert(all.end(), sweepColourFigureNames().begin(), sweepColourFigureNames().end());
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

const std::vector<std::string>& sweepColourFigureNames() {
    static const std::vector<std::string> names = [] {
        std::vector<std::string> all;
        for (const ColourFigureRow& f : kColourFigures) all.emplace_back(f.key);
        return all;
    }();
    return names;
}

std::vector<std::string> sweepFigureNames(const TraceSettings& trace, bool colour) {
    std::vector<std::string> names;
    if (trace.viewer.enabled) names = sweepViewerFigureNames();
    names.insert(names.end(), sweepPlainFigureNames().begin(), sweepPlainFigureNames().end());
    if (trace.fire.enabled)
        names.insert(names.end(), sweepFireFigureNames().begin(), sweepFireFigureNames().end());
    if (colour) names.insert(names.end(), sweepColourFigureNames().begin(), sweepColourFigureNames().end());
    return names;
}

void checkSweepFigure(const std::string& name, const TraceSettings& trace, bool colour) {
    const auto& names = sweepFigureNames();
    if (!contains(names, name)) {
        std::string list;
        for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
        throw Error("unknown figure '" + name + "'; the figures are: " + list);
    }
    if (!trace.viewer.enabled && contains(sweepViewerFigureNames(), name))
        throw Error("the figure " + name +
                    " is a viewer figure, and the viewer is off: turn it on (drop --no-view, or a job's "
                    "viewer.enabled false)");
    if (!trace.fire.enabled && contains(sweepFireFigureNames(), name))
        throw Error(
            "the figure " + name +
            " is measured by a fire trace, which is off: turn it on (--fire, or a job's fire.enabled)");
    if (!colour && contains(sweepColourFigureNames(), name))
        throw Error("the figure " + name +
                    " is measured by the colour view, which is off: turn it on (--colour or a --colour-... "
                    "flag, or a job's colour object) with an absorbing material");
}

std::string sweepFigureUnit(const std::string& name) {
    if (name == "mean_separation_deg") return "deg";
    for (const ColourFigureRow& f : kColourFigures)
        if (name == f.key) return f.figure ? "CIELAB" : "";
    return "";
}

nlohmann::json sweepColourFigures(const ColourView& view) {
    nlohmann::json out = nlohmann::json::object();
    for (const ColourFigureRow& f : kColourFigures) {
        const std::string key = f.key;
        if (f.figure) {
            out[key] = (view.*f.figure).mean;
            out[key + "_stderr"] = (view.*f.figure).meanError;
        } else {
            out[key] = (view.*f.share).share;
            out[key + "_stderr"] = (view.*f.share).standardError;
        }
    }
    return out;
}
}  // namespace facetlight
