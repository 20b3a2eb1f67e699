#include "sweep/sweep_pictures.h"

#include <algorithm>
#include <cstdio>

#include "cuts/facet_design.h"
#include "pictures/sweep_plot.h"
#include "sweep/sweep_figures.h"
#include "sweep/sweep_references.h"
#include "scene/scene.h"
#include "util/error.h"
#include "util/name_table.h"

namespace facetlight {
namespace {

PlotAxis plotAxis(const SweepPlan& plan, const SweepAxis& axis) {
    const std::string unit = plan.unit(axis);
    // "size (mm)", not "size mm (mm)".
    const std::string name = !unit.empty() && axis.name.ends_with("_" + unit)
                                 ? axis.name.substr(0, axis.name.size() - unit.size() - 1)
                                 : axis.name;
    return {spacedName(name) + (unit.empty() ? "" : " (" + unit + ")"), axis.values, axis.choices};
}

// The y axis's name: what the figures drawn on it are, each kind named once.
std::string yAxisLabel(const std::vector<std::string>& figures) {
    struct Kind {
        std::string alone, together;
        bool present = false;
    };
    Kind kinds[] = {{"share of the photons hitting the stone", "share of the hits"},
                    {"share of the face-up area", "share of the face-up area"},
                    {"degrees", "mean separation in degrees"},
                    {"CIELAB units", "L*, a*, b*, C*ab in CIELAB units"}};
    const auto& colour = sweepColourFigureNames();
    for (const std::string& f : figures) {
        const std::string unit = sweepFigureUnit(f);
        const bool colourFigure = std::find(colour.begin(), colour.end(), f) != colour.end();
        kinds[unit == "deg" ? 2 : unit == "CIELAB" ? 3 : colourFigure ? 1 : 0].present = true;
    }
    std::string label;
    size_t count = 0;
    for (const Kind& k : kinds) count += k.present;
    for (const Kind& k : kinds)
        if (k.present) label += (label.empty() ? "" : "; ") + (count == 1 ? k.alone : k.together);
    return label;
}

// The axes that take more than one value.
std::vector<size_t> variedAxes(const SweepPlan& plan) {
    std::vector<size_t> out;
    for (size_t a = 0; a < plan.axes.size(); ++a)
        if (plan.axes[a].size() > 1) out.push_back(a);
    return out;
}

PlotSeries figureSeries(const SweepResult& result, const std::string& figure) {
    checkSweepFigure(figure, result.plan.trace, result.plan.colour.has_value());
    PlotSeries s{spacedName(figure), {}, {}, {}};
    for (const SweepPoint& p : result.points) {
        s.valid.push_back(p.ok());
        s.value.push_back(p.ok() ? p.figure(figure) : 0.0);
        s.sigma.push_back(p.ok() ? p.stderrOf(figure) : 0.0);
    }
    return s;
}

// The design, the parameters held at other than their defaults ("crown 34.5"), the light and the photons.
std::string settingsLine(const SweepResult& result) {
    const TraceSettings& t = result.plan.trace;
    std::string held;
    for (const auto& [name, value] : result.plan.fixed) {
        char text[64];
        std::snprintf(text, sizeof text, "%s %g", spacedName(name).c_str(), value);
        held += std::string(held.empty() ? " with " : ", ") + text;
    }
    // With the colour view: its illuminant, and the material and size where no axis varies them.
    std::string colour;
    if (const std::optional<ColourSettings>& c = result.plan.colour) {
        const auto varied = [&](const char* name) {
            return std::any_of(result.plan.axes.begin(), result.plan.axes.end(),
                               [&](const SweepAxis& a) { return a.name == name; });
        };
        colour = "; colour under " + std::string(kIlluminantNames.name(c->illuminant));
        if (!varied("material") && !varied("n"))
            colour +=
                ", " + (t.constantIndex ? "n " + formatNumber(*t.constantIndex) : chosenMaterialName(t));
        if (!varied("size_mm")) colour += " at " + formatNumber(t.sizeMm) + " mm";
    }
    return result.plan.shape + held + "; " + std::string(kLightModelNames.name(t.light.model)) + " light, " +
           std::to_string(t.photons) + " photons a point" + colour;
}

// "; highest brightness 0.4110 +- 0.0021 at pavilion 41.75", for the curves' title.
std::string highestText(const SweepResult& result, const std::string& figure, const SweepAxis& axis, size_t a) {
    const std::optional<size_t> best = highestPoint(result, figure);
    if (!best) return "";
    const SweepPoint& p = result.points[*best];
    char text[160];
    std::snprintf(text, sizeof text, "; highest %s %.4f +- %.4f at %s %s", spacedName(figure).c_str(),
                  p.figure(figure), p.stderrOf(figure), spacedName(axis.name).c_str(), axis.label(p.at[a]).c_str());
    return text;
}

}  // namespace

std::optional<size_t> highestPoint(const SweepResult& result, const std::string& figure) {
    checkSweepFigure(figure, result.plan.trace, result.plan.colour.has_value());
    std::optional<size_t> best;
    for (size_t k = 0; k < result.points.size(); ++k) {
        const SweepPoint& p = result.points[k];
        if (p.ok() && (!best || p.figure(figure) > result.points[*best].figure(figure))) best = k;
    }
    return best;
}

std::string sweepCurvesTitle(const SweepResult& result, const std::vector<std::string>& figures) {
    const std::vector<size_t> varied = variedAxes(result.plan);
    const size_t a = varied.empty() ? 0 : varied[0];
    return settingsLine(result) + highestText(result, figures.front(), result.plan.axes[a], a);
}

Image sweepCurves(const SweepResult& result, const std::vector<std::string>& figures) {
    const std::vector<size_t> varied = variedAxes(result.plan);
    if (varied.size() > 1) throw Error("a sweep over two quantities is drawn as maps, not curves");
    const SweepAxis& axis = result.plan.axes[varied.empty() ? 0 : varied[0]];
    std::vector<PlotSeries> series;
    for (const std::string& f : figures) series.push_back(figureSeries(result, f));
    // One y axis for every figure drawn, its label naming each kind.
    return seriesPlot(plotAxis(result.plan, axis), series, yAxisLabel(figures),
                      sweepCurvesTitle(result, figures));
}

Image sweepMap(const SweepResult& result, const std::string& figure) {
    const SweepPlan& plan = result.plan;
    if (plan.axes.size() != 2) throw Error("a map needs a sweep over two quantities");
    const SweepAxis &ax = plan.axes[0], &ay = plan.axes[1];
    std::vector<PlotMarker> markers;
    if (const std::optional<size_t> best = highestPoint(result, figure)) {
        const SweepPoint& p = result.points[*best];
        char value[64];
        std::snprintf(value, sizeof value, "%.4f +- %.4f", p.figure(figure), p.stderrOf(figure));
        markers.push_back({plotAxis(plan, ax).position(p.at[0]), plotAxis(plan, ay).position(p.at[1]),
                           "highest " + std::string(value) + " at " + ax.name + " " + ax.label(p.at[0]) +
                               ", " + ay.name + " " + ay.label(p.at[1]),
                           true});
    }
    for (const SweepReference& r : sweepReferences(plan))
        markers.push_back({r.values[0], r.values[1], r.label, false});
    return contourMap(plotAxis(plan, ax), plotAxis(plan, ay), figureSeries(result, figure),
                      spacedName(figure), markers, spacedName(figure) + ", " + settingsLine(result));
}

std::vector<std::pair<std::string, Image>> sweepPictures(const SweepResult& result,
                                                         const std::vector<std::string>& figures) {
    for (const std::string& f : figures)
        checkSweepFigure(f, result.plan.trace, result.plan.colour.has_value());
    std::vector<std::pair<std::string, Image>> out;
    if (variedAxes(result.plan).size() < 2) {
        out.emplace_back("curves.png", sweepCurves(result, figures));
        return out;
    }
    for (const std::string& f : figures) out.emplace_back("map_" + f + ".png", sweepMap(result, f));
    return out;
}

}  // namespace facetlight
