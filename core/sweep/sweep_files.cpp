#include "sweep/sweep_files.h"

#include <algorithm>
#include <sstream>

#include "sweep/sweep_figures.h"
#include "util/error.h"

namespace facetlight {

nlohmann::json sweepPointJson(const SweepPlan& plan, const SweepPoint& p) {
    nlohmann::json values = nlohmann::json::object();
    for (size_t a = 0; a < plan.axes.size(); ++a) {
        const SweepAxis& axis = plan.axes[a];
        values[axis.name] =
            axis.numeric() ? nlohmann::json(axis.values[p.at[a]]) : nlohmann::json(axis.choices[p.at[a]]);
    }
    nlohmann::json point = {{"at", p.at}, {"values", values}};
    if (p.ok()) {
        point["proportions"] = p.proportions;
        point["totals"] = p.totals;
        if (p.trace.fire.enabled) point["fire"] = p.fire;
        if (p.trace.viewer.enabled) point["viewer"] = p.viewer;
        if (plan.colour) point["colour"] = p.colour;
    } else {
        point["error"] = p.error;
    }
    return point;
}

void restoreSweepPoint(const SweepPlan& plan, const nlohmann::json& j, SweepPoint& point) {
    if (!j.is_object() || j.value("at", nlohmann::json()) != nlohmann::json(point.at))
        throw Error("a stored sweep point does not belong to this grid");
    if (j.contains("error")) {
        point.error = j["error"].get<std::string>();
        if (point.error.empty()) throw Error("a stored sweep point has an empty error");
        return;
    }
    if (point.trace.fire.enabled && !j.contains("fire"))
        throw Error("a stored sweep point has no fire figures, and the sweep traces fire");
    if (point.trace.viewer.enabled && !j.contains("viewer"))
        throw Error("a stored sweep point has no viewer figures, and the sweep has the viewer on");
    if (plan.colour && !j.contains("colour"))
        throw Error("a stored sweep point has no colour figures, and the sweep has the colour view");
    point.error.clear();
    point.proportions = j.at("proportions");
    point.totals = j.at("totals");
    if (point.trace.fire.enabled) point.fire = j.at("fire");
    if (point.trace.viewer.enabled) point.viewer = j.at("viewer");
    if (plan.colour) point.colour = j.at("colour");
}

nlohmann::json sweepAxesJson(const SweepPlan& plan) {
    nlohmann::json axes = nlohmann::json::array();
    for (const SweepAxis& a : plan.axes) {
        nlohmann::json axis = {{"name", a.name}, {"unit", plan.unit(a)}};
        if (a.numeric()) {
            axis["values"] = a.values;
        } else {
            axis["choices"] = a.choices;
        }
        axes.push_back(axis);
    }
    return axes;
}

nlohmann::json sweepToJson(const SweepResult& result) {
    const SweepPlan& plan = result.plan;
    nlohmann::json fixed = nlohmann::json::object();
    // A named pair, not a structured binding: clang 14 (the fuzz build) cannot capture bindings in lambdas.
    for (const auto& parameter : completeCutValues(plan.cutShape(), plan.fixed)) {
        const bool varied = std::any_of(plan.axes.begin(), plan.axes.end(),
                                        [&](const SweepAxis& a) { return a.name == parameter.first; });
        if (!varied) fixed[parameter.first] = parameter.second;
    }
    nlohmann::json points = nlohmann::json::array();
    for (const SweepPoint& p : result.points) points.push_back(sweepPointJson(plan, p));
    nlohmann::json out = {
        {"shape", plan.shape},
        {"fixed", fixed},
        {"settings", toJson(plan.trace)},
        {"axes", sweepAxesJson(plan)},
        {"figures", sweepFigureNames(plan.trace, plan.colour.has_value())},
        {"points", points},
        {"timing",
         {{"seconds", result.seconds},
          {"points_per_second", result.seconds > 0 ? double(result.points.size()) / result.seconds : 0.0},
          {"threads", plan.trace.threads}}}};
    if (plan.colour) out["colour"] = colourSettingsSchema().write(*plan.colour);
    return out;
}

std::string sweepCsv(const SweepResult& result) {
    const SweepPlan& plan = result.plan;
    static const std::vector<std::string> depths{"crown_height_pct", "pavilion_depth_pct", "total_depth_pct"};
    std::ostringstream out;
    out.precision(9);
    for (const SweepAxis& a : plan.axes) out << a.name << ',';
    for (const std::string& d : depths) out << d << ',';
    out << "hit";
    const std::vector<std::string> figures = sweepFigureNames(plan.trace, plan.colour.has_value());
    for (const std::string& f : figures) out << ',' << f << ',' << f << "_stderr";
    out << ",error\n";
    for (const SweepPoint& p : result.points) {
        for (size_t a = 0; a < plan.axes.size(); ++a) out << plan.axes[a].label(p.at[a]) << ',';
        for (const std::string& d : depths) {
            if (p.ok() && p.proportions[d].is_number()) out << p.proportions[d].get<double>();
            out << ',';
        }
        if (p.ok()) out << p.totals["hit"].get<uint64_t>();
        for (const std::string& f : figures) {
            if (p.ok()) {
                out << ',' << p.figure(f) << ',' << p.stderrOf(f);
            } else {
                out << ",,";
            }
        }
        // Messages are the library's own; quoted with embedded quotes doubled (RFC 4180).
        std::string error;
        for (char c : p.error) error += c == '"' ? std::string("\"\"") : std::string(1, c);
        out << ',' << (p.ok() ? "" : "\"" + error + "\"") << '\n';
    }
    return out.str();
}
}  // namespace facetlight
