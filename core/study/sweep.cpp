#include "study/sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "cuts/facet_design.h"
#include "scene/scene.h"
#include "stats/fire_stats.h"
#include "study/study.h"
#include "trace/photon_tracer.h"
#include "util/error.h"
#include "util/number_text.h"
#include "util/parallel.h"

namespace facetlight {
namespace {

bool isTraceAxis(const std::string& name) {
    return std::find(kTraceAxes.begin(), kTraceAxes.end(), name) != kTraceAxes.end();
}

// Throws Error naming the field when the settings' table refuses them.
void checkTraceSettings(const TraceSettings& t) {
    TraceSettings::fromJson(toJson(t));
}

bool isChoiceAxis(const std::string& name) {
    return name == "material" || name == "light";
}

std::vector<std::string> splitText(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.push_back("");
    return parts;
}

double axisNumber(const std::string& axis, const std::string& token) {
    double v = 0;
    if (!parseNumber(token, v) || !std::isfinite(v))
        throw Error("sweep axis " + axis + ": '" + token + "' is not a number");
    return v;
}

// The setting or parameter `axis` takes at index i, applied to a point's design.
void applyAxis(const SweepAxis& axis, size_t i, CutValues& cut, TraceSettings& trace) {
    if (axis.name == "tilt") {
        trace.light.tiltDeg = axis.values[i];
    } else if (axis.name == "head_shadow") {
        trace.light.headShadowDeg = axis.values[i];
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

std::string SweepAxis::label(size_t i) const {
    return numeric() ? formatNumber(values[i]) : choices[i];
}

SweepAxis sweepRange(const std::string& name, double lo, double hi, double step) {
    const std::string range = formatNumber(lo) + ":" + formatNumber(hi) + ":" + formatNumber(step);
    if (!(step > 0))
        throw Error("sweep axis " + name + ": the step must be above 0, got " + formatNumber(step));
    if (hi < lo) throw Error("sweep axis " + name + ": the range " + range + " is inverted (HI below LO)");
    const double steps = std::floor((hi - lo) / step + 1e-9);
    if (steps + 1 > double(kMaxSweepPoints))
        throw Error("sweep axis " + name + ": " + range + " has more than " +
                    std::to_string(kMaxSweepPoints) + " values");
    // lo + i step, rounded to nine decimals so that 37.3 is the number a user typing 37.3 gets.
    SweepAxis axis{name, {}, {}};
    for (int i = 0; i <= int(steps); ++i) axis.values.push_back(std::round((lo + i * step) * 1e9) / 1e9);
    return axis;
}

SweepAxis parseSweepAxis(const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw Error("sweep axis '" + text + "': write NAME=LO:HI:STEP or NAME=V1,V2,...");
    SweepAxis axis;
    axis.name = text.substr(0, eq);
    const std::string range = text.substr(eq + 1);
    if (isChoiceAxis(axis.name)) {
        for (const std::string& choice : splitText(range, ',')) {
            if (choice.empty()) throw Error("sweep axis " + axis.name + ": an empty name in '" + range + "'");
            axis.choices.push_back(choice);
        }
    } else if (range.find(':') != std::string::npos) {
        const std::vector<std::string> parts = splitText(range, ':');
        if (parts.size() != 3)
            throw Error("sweep axis " + axis.name + ": a range is LO:HI:STEP, got '" + range + "'");
        axis = sweepRange(axis.name, axisNumber(axis.name, parts[0]), axisNumber(axis.name, parts[1]),
                          axisNumber(axis.name, parts[2]));
    } else {
        for (const std::string& token : splitText(range, ','))
            axis.values.push_back(axisNumber(axis.name, token));
    }
    if (axis.size() > kMaxSweepPoints)
        throw Error("sweep axis " + axis.name + " has more than " + std::to_string(kMaxSweepPoints) +
                    " values");
    return axis;
}

size_t SweepSpec::pointCount() const {
    size_t n = axes.empty() ? 0 : 1;
    for (const SweepAxis& a : axes) n *= a.size();
    return n;
}

std::string SweepSpec::unit(const SweepAxis& axis) const {
    if (axis.name == "tilt" || axis.name == "head_shadow") return "deg";
    if (isTraceAxis(axis.name)) return "";
    for (const CutParameter& p : findCutShape(shape).parameters)
        if (p.name == axis.name) return p.unit;
    return "";
}

void SweepSpec::validate() const {
    const CutShape& s = findCutShape(shape);
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

std::vector<SweepPoint> sweepPoints(const SweepSpec& spec) {
    const CutShape& shape = findCutShape(spec.shape);
    std::vector<SweepPoint> points(spec.pointCount());
    for (size_t k = 0; k < points.size(); ++k) {
        SweepPoint& p = points[k];
        p.at.resize(spec.axes.size());
        size_t rest = k;
        for (size_t a = spec.axes.size(); a-- > 0;) {
            p.at[a] = rest % spec.axes[a].size();
            rest /= spec.axes[a].size();
        }
        CutValues cut = spec.fixed;
        p.trace = spec.trace;
        for (size_t a = 0; a < spec.axes.size(); ++a) applyAxis(spec.axes[a], p.at[a], cut, p.trace);
        p.cut = completeCutValues(shape, cut);
    }
    return points;
}

SweepResult runSweep(const SweepSpec& spec, RunControl& control, const SweepPointHooks& hooks) {
    SerialCommunicator serial;
    return runSweep(spec, control, hooks, serial);
}

SweepResult runSweep(const SweepSpec& spec, RunControl& control, const SweepPointHooks& hooks,
                     Communicator& comm) {
    spec.validate();
    const auto start = std::chrono::steady_clock::now();
    SweepResult result{spec, sweepPoints(spec), 0};
    const CutShape& shape = findCutShape(spec.shape);
    const int threads = spec.trace.threads;
    const size_t count = result.points.size();

    // Points finished before, read on rank 0 and handed to every rank.
    std::string restoredText;
    if (comm.isRoot() && hooks.restore) {
        nlohmann::json restored = nlohmann::json::object();
        for (size_t k = 0; k < count; ++k)
            if (std::optional<nlohmann::json> j = hooks.restore(k))
                restored[std::to_string(k)] = std::move(*j);
        restoredText = restored.dump();
    }
    if (comm.size() > 1) comm.broadcast(restoredText);
    std::vector<bool> pending(count, true);
    if (!restoredText.empty()) {
        const nlohmann::json restored = nlohmann::json::parse(restoredText);
        for (const auto& [key, j] : restored.items()) {
            const size_t k = std::stoul(key);
            // A point kept by a build that reported no fire figures is traced again.
            if (result.points.at(k).trace.fire.enabled && j.contains("totals") && !j.contains("fire"))
                continue;
            restoreSweepPoint(j, result.points.at(k));
            pending[k] = false;
        }
    }
    // This rank's points: every size-th of those still to trace.
    std::vector<size_t> mine;
    for (size_t k = 0; k < count; ++k)
        if (pending[k] && k % size_t(comm.size()) == size_t(comm.rank())) mine.push_back(k);

    // Each distinct design once: points that differ only in trace settings share its stone.
    std::map<CutValues, size_t> designIndex;
    std::vector<const CutValues*> designs;
    std::vector<size_t> designOf(count);
    for (const size_t k : mine) {
        const auto [it, added] = designIndex.emplace(result.points[k].cut, designs.size());
        if (added) designs.push_back(&it->first);
        designOf[k] = it->second;
    }
    if (anyRank(comm, control.cancelled())) throw Canceled();
    std::vector<std::optional<Stone>> stones(designs.size());
    std::vector<std::string> designError(designs.size());
    parallelForBlocks({0, designs.size(), 1, threads}, &control, [&](int, uint64_t first, uint64_t last) {
        for (uint64_t d = first; d < last; ++d) {
            try {
                stones[d] = Stone::build(shape.build(*designs[d]), spec.shape);
            } catch (const Error& e) {
                designError[d] = e.what();
            }
        }
        return uint64_t(0);
    });
    if (anyRank(comm, control.cancelled())) throw Canceled();

    // Several points at once; the threads left over trace within each (a trace's bits do not depend on them).
    // Progress counts photons, so that a cancel stops a point within a block of them.
    control.startPhase(RunPhase::Tracing, mine.size() * spec.trace.photons);
    for (size_t k = 0; k < count; ++k)
        if (!pending[k]) control.finishItem();
    const BlockLoop loop{0, mine.size(), 1, threads};
    const int inner = std::max(1, threads / loop.workers());
    const bool finished = parallelForBlocks(loop, &control, [&](int, uint64_t first, uint64_t last) {
        for (uint64_t i = first; i < last; ++i) {
            const size_t k = mine[i];
            SweepPoint& p = result.points[k];
            const std::optional<Stone>& stone = stones[designOf[k]];
            p.error = designError[designOf[k]];
            if (stone) {
                try {
                    TraceSettings settings = p.trace;
                    settings.threads = inner;
                    const Scene scene(*stone, settings);
                    TraceResult traced = trace(TraceBase(scene, settings), &control);
                    if (traced.cancelled) return uint64_t(0);
                    nlohmann::json stats = traceReport(traced, *stone, p.trace);
                    p.totals = std::move(stats["totals"]);
                    p.proportions = std::move(stats["mesh"]["proportions"]);
                    if (traced.fire) {
                        const nlohmann::json& fire = stats.at("fire");
                        p.fire = nlohmann::json::object();
                        for (const std::string& f : sweepFireFigureNames())
                            for (const std::string& key : {f, f + "_stderr"}) p.fire[key] = fire.at(key);
                    }
                    p.stats = std::move(traced.stats);
                } catch (const Error& e) {
                    p.error = e.what();
                }
            }
            if (!p.ok()) control.advance(p.trace.photons);
            if (hooks.onPoint) hooks.onPoint(k, p);  // kept before it counts as done
            control.finishItem();
        }
        return uint64_t(0);
    });
    if (anyRank(comm, !finished || control.cancelled())) throw Canceled();

    if (comm.size() > 1) {
        nlohmann::json traced = nlohmann::json::object();
        for (const size_t k : mine) traced[std::to_string(k)] = sweepPointJson(spec, result.points[k]);
        for (const std::string& bytes : comm.allGather(traced.dump())) {
            const nlohmann::json points = nlohmann::json::parse(bytes);
            for (const auto& [key, j] : points.items()) {
                const size_t k = std::stoul(key);
                if (k % size_t(comm.size()) == size_t(comm.rank())) continue;
                restoreSweepPoint(j, result.points.at(k));
                if (comm.isRoot() && hooks.onPoint) hooks.onPoint(k, result.points[k]);
            }
        }
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    control.startPhase(RunPhase::Done, 0);
    return result;
}

nlohmann::json sweepPointJson(const SweepSpec& spec, const SweepPoint& p) {
    nlohmann::json values = nlohmann::json::object();
    for (size_t a = 0; a < spec.axes.size(); ++a) {
        const SweepAxis& axis = spec.axes[a];
        values[axis.name] =
            axis.numeric() ? nlohmann::json(axis.values[p.at[a]]) : nlohmann::json(axis.choices[p.at[a]]);
    }
    nlohmann::json point = {{"at", p.at}, {"values", values}};
    if (p.ok()) {
        point["proportions"] = p.proportions;
        point["totals"] = p.totals;
        if (p.trace.fire.enabled) point["fire"] = p.fire;
    } else {
        point["error"] = p.error;
    }
    return point;
}

void restoreSweepPoint(const nlohmann::json& j, SweepPoint& point) {
    if (!j.is_object() || j.value("at", nlohmann::json()) != nlohmann::json(point.at))
        throw Error("a stored sweep point does not belong to this grid");
    if (j.contains("error")) {
        point.error = j["error"].get<std::string>();
        if (point.error.empty()) throw Error("a stored sweep point has an empty error");
        return;
    }
    if (point.trace.fire.enabled && !j.contains("fire"))
        throw Error("a stored sweep point has no fire figures, and the sweep traces fire");
    point.error.clear();
    point.proportions = j.at("proportions");
    point.totals = j.at("totals");
    if (point.trace.fire.enabled) point.fire = j.at("fire");
}

nlohmann::json sweepAxesJson(const SweepSpec& spec) {
    nlohmann::json axes = nlohmann::json::array();
    for (const SweepAxis& a : spec.axes) {
        nlohmann::json axis = {{"name", a.name}, {"unit", spec.unit(a)}};
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
    const SweepSpec& spec = result.spec;
    nlohmann::json fixed = nlohmann::json::object();
    // A named pair, not a structured binding: clang 14 (the fuzz build) cannot capture bindings in lambdas.
    for (const auto& parameter : completeCutValues(findCutShape(spec.shape), spec.fixed)) {
        const bool varied = std::any_of(spec.axes.begin(), spec.axes.end(),
                                        [&](const SweepAxis& a) { return a.name == parameter.first; });
        if (!varied) fixed[parameter.first] = parameter.second;
    }
    nlohmann::json points = nlohmann::json::array();
    for (const SweepPoint& p : result.points) points.push_back(sweepPointJson(spec, p));
    return {{"shape", spec.shape},
            {"fixed", fixed},
            {"settings", toJson(spec.trace)},
            {"axes", sweepAxesJson(spec)},
            {"figures", sweepFigureNames(spec.trace)},
            {"points", points},
            {"timing",
             {{"seconds", result.seconds},
              {"points_per_second", result.seconds > 0 ? double(result.points.size()) / result.seconds : 0.0},
              {"threads", spec.trace.threads}}}};
}

std::string sweepCsv(const SweepResult& result) {
    const SweepSpec& spec = result.spec;
    static const std::vector<std::string> depths{"crown_height_pct", "pavilion_depth_pct", "total_depth_pct"};
    std::ostringstream out;
    out.precision(9);
    for (const SweepAxis& a : spec.axes) out << a.name << ',';
    for (const std::string& d : depths) out << d << ',';
    out << "hit";
    const std::vector<std::string> figures = sweepFigureNames(spec.trace);
    for (const std::string& f : figures) out << ',' << f << ',' << f << "_stderr";
    out << ",error\n";
    for (const SweepPoint& p : result.points) {
        for (size_t a = 0; a < spec.axes.size(); ++a) out << spec.axes[a].label(p.at[a]) << ',';
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
