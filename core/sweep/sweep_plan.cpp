#include "sweep/sweep_plan.h"

#include <algorithm>
#include <optional>
#include <set>

#include "scene/scene.h"
#include "util/error.h"

namespace facetlight {
namespace {

// Throws Error naming the field when the settings' table refuses them.
void checkTraceSettings(const TraceSettings& t) {
    TraceSettings::fromJson(toJson(t));
}

// The setting or parameter `axis` takes at index i, applied to a point's design.
void applyAxis(const SweepAxis& axis, size_t i, CutValues& cut, TraceSettings& trace) {
    if (axis.name == "tilt") {
        trace.light.tiltDeg = axis.values[i];
    } else if (axis.name == "head_shadow") {
        trace.light.headShadowDeg = axis.values[i];
    } else if (axis.name == "n") {
        trace.constantIndex = axis.values[i];
    } else if (axis.name == "optic_axis_tilt") {
        trace.opticAxis.tiltDeg = axis.values[i];
    } else if (axis.name == "optic_axis_azimuth") {
        trace.opticAxis.azimuthDeg = axis.values[i];
    } else if (axis.name == "optic_axis_rotation") {
        trace.opticAxis.rotationDeg = axis.values[i];
    } else if (axis.name == "size_mm") {
        trace.sizeMm = axis.values[i];
    } else if (axis.name == "material") {
        trace.material = axis.choices[i];
    } else if (axis.name == "light") {
        const std::optional<LightModelKind> model = kLightModelNames.find(axis.choices[i]);
        if (!model) throw Error("sweep axis light: no light model '" + axis.choices[i] + "'");
        trace.light.model = *model;
    } else {
        cut[axis.name] = axis.values[i];
    }
}

}  // namespace

size_t SweepPlan::pointCount() const {
    size_t n = axes.empty() ? 0 : 1;
    for (const SweepAxis& a : axes) n *= a.size();
    return n;
}

std::string SweepPlan::unit(const SweepAxis& axis) const {
    if (axis.name == "tilt" || axis.name == "head_shadow" || axis.name.starts_with("optic_axis_"))
        return "deg";
    if (axis.name == "size_mm") return "mm";
    if (isTraceAxis(axis.name)) return "";
    for (const CutParameter& p : cutShape().parameters)
        if (p.name == axis.name) return p.unit;
    return "";
}

// The optic axis means something to a doubly refracting stone traced polarised (docs/optics.md,
// "Birefringent stones", "Biaxial crystals"), the turn of X about Z to a biaxial one only, and only the job's
// own material's: a material axis would change the stone under it.
void SweepPlan::checkOpticAxisSweep(const std::string& name) const {
    if (std::any_of(axes.begin(), axes.end(),
                    [](const SweepAxis& a) { return a.name == "material" || a.name == "n"; }))
        throw Error("sweep axis " + name +
                    " turns one material's optic axis: sweep it without a material or n axis");
    const Optic optic = chosenOptic(trace);
    if (name == "optic_axis_rotation" && optic != Optic::Biaxial)
        throw Error("sweep axis " + name + " needs a biaxial material, whose X axis it turns about Z (got " +
                    chosenMaterialName(trace) + ")");
    if (optic == Optic::Isotropic)
        throw Error("sweep axis " + name +
                    " needs a doubly refracting (uniaxial or biaxial) material, whose axes it turns (got " +
                    chosenMaterialName(trace) + ")");
    if (trace.polarization == PolarizationMode::Off)
        throw Error("sweep axis " + name +
                    " needs polarization on: unpolarised tracing sees one index and no optic axis");
}

void SweepPlan::validate() const {
    const CutShape& s = cutShape();
    completeCutValues(s, fixed);
    checkTraceSettings(trace);
    if (axes.empty() || axes.size() > kMaxSweepAxes)
        throw Error("a sweep varies 1 or 2 quantities, got " + std::to_string(axes.size()));
    std::set<std::string> seen;
    for (const SweepAxis& axis : axes) {
        if (!seen.insert(axis.name).second) throw Error("sweep axis " + axis.name + " is given twice");
        if (fixed.count(axis.name)) throw Error(axis.name + " is both varied and fixed");
        const bool param = std::any_of(s.parameters.begin(), s.parameters.end(),
                                       [&](const CutParameter& p) { return p.name == axis.name; });
        if (!param && !isTraceAxis(axis.name)) {
            std::string names;
            for (const CutParameter& p : s.parameters) names += p.name + ", ";
            for (const std::string& t : kTraceAxes) names += t + (t == kTraceAxes.back() ? "" : ", ");
            throw Error("sweep axis '" + axis.name + "' is neither a parameter of " + shape +
                        " nor a trace setting; the axes are: " + names);
        }
        if (axis.size() == 0) throw Error("sweep axis " + axis.name + " has no values");
        if (trace.customMaterial && (axis.name == "material" || axis.name == "n"))
            throw Error("sweep axis " + axis.name +
                        " would replace the job's own material (custom_material): sweep one or the other");
        if (axis.name.starts_with("optic_axis_")) checkOpticAxisSweep(axis.name);
        if (axis.numeric() == isChoiceAxis(axis.name))
            throw Error("sweep axis " + axis.name + (axis.numeric() ? " takes names" : " takes numbers"));
        for (size_t i = 0; i < axis.size(); ++i) {
            CutValues cut;
            TraceSettings t = trace;
            applyAxis(axis, i, cut, t);
            if (param) {
                completeCutValues(s, cut);
            } else {
                checkTraceSettings(t);
            }
        }
    }
    if (pointCount() > kMaxSweepPoints)
        throw Error("the sweep has " + std::to_string(pointCount()) + " points; at most " +
                    std::to_string(kMaxSweepPoints) + " are allowed");
}

std::vector<SweepPoint> sweepPoints(const SweepPlan& plan) {
    const CutShape& shape = plan.cutShape();
    std::vector<SweepPoint> points(plan.pointCount());
    for (size_t k = 0; k < points.size(); ++k) {
        SweepPoint& p = points[k];
        p.at.resize(plan.axes.size());
        size_t rest = k;
        for (size_t a = plan.axes.size(); a-- > 0;) {
            p.at[a] = rest % plan.axes[a].size();
            rest /= plan.axes[a].size();
        }
        CutValues cut = plan.fixed;
        p.trace = plan.trace;
        for (size_t a = 0; a < plan.axes.size(); ++a) applyAxis(plan.axes[a], p.at[a], cut, p.trace);
        p.cut = completeCutValues(shape, cut);
    }
    return points;
}
}  // namespace facetlight
