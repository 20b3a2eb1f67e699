#include "viewer/verdict.h"

#include <cmath>
#include <map>
#include <memory>
#include <mutex>

#include "cuts/cut_library.h"
#include "util/number_text.h"

namespace facetlight {
namespace {

// a / b - 1 in percent, with its standard error (a and b independent).
ViewerFigure relativeDifference(const ViewerFigure& a, const ViewerFigure& b) {
    if (!(b.value > 0)) return {};
    const double ratio = a.value / b.value;
    const double relA = a.value > 0 ? a.stderr / a.value : 0, relB = b.stderr / b.value;
    return {100 * (ratio - 1), 100 * ratio * std::hypot(relA, relB)};
}

std::string percentText(const ViewerFigure& v) {
    return formatWithError(100 * v.value, 100 * v.stderr) + " %";
}

// "brightness 40.6 +- 0.1 %, 7.3 % +- 0.6 above the GIA reference's 37.9 %"; within two standard errors of
// the reference, "as the GIA reference's".
std::string comparisonText(const FigureComparison& c) {
    const ViewerFigure& d = c.difference;
    std::string text = std::string(c.info->label) + " " + percentText(c.stone) + ", ";
    if (std::abs(d.value) < 2 * d.stderr)
        return text + "as the GIA reference's (" + percentText(c.reference) + ")";
    return text + formatWithError(std::abs(d.value), d.stderr) + " % " + (d.value > 0 ? "above" : "below") +
           " the GIA reference's " + percentText(c.reference);
}

// The settings the reference's figures depend on (not the threads: the figures do not).
std::string referenceKey(const TraceSettings& t) {
    nlohmann::json j = toJson(t);
    j.erase("threads");
    j.erase("photons");
    j.erase("light");
    j.erase("fire");
    return j.dump();
}

}  // namespace

const char* const kReferenceName =
    "the GIA reference round brilliant (T 57, C 34, P 40.7, girdle 2.5, star 50, lower half 80)";

const ViewerFigures& referenceFigures(const TraceSettings& trace, RunControl* control) {
    static std::mutex mutex;
    static std::map<std::string, std::unique_ptr<ViewerFigures>> traced;
    const std::string key = referenceKey(trace);
    {
        const std::lock_guard<std::mutex> lock(mutex);
        if (const auto it = traced.find(key); it != traced.end()) {
            if (control) control->advance(viewerUnits(trace.viewer));  // as if traced again
            return *it->second;
        }
    }
    static const Stone stone = Stone::build(makeCut("round_brilliant"), "GIA reference");
    auto figures = std::make_unique<ViewerFigures>(viewStone(stone, trace, control));
    if (figures->cancelled) throw Canceled();
    const std::lock_guard<std::mutex> lock(mutex);
    return *traced.emplace(key, std::move(figures)).first->second;
}

Verdict judge(const Stone& stone, const ViewerFigures& figures, const ViewerFigures& reference) {
    Verdict v;
    v.reference = kReferenceName;
    for (const ViewerFigureInfo& info : kViewerFigures) {
        FigureComparison c{&info, (figures.*info.get)(), (reference.*info.get)(), {}, {}};
        c.difference = relativeDifference(c.stone, c.reference);
        c.text = comparisonText(c);
        v.figures.push_back(std::move(c));
    }
    const double elongation =
        stone.proportions.width > 0 ? stone.proportions.length / stone.proportions.width : 1.0;
    for (const FaultRule& rule : kFaultRules) {
        FaultFinding f{&rule, (figures.*rule.measure)(), true, false, {}};
        f.applies = !rule.elongatedOnly || std::max(elongation, 1 / elongation) >= kElongated;
        f.present = f.applies && f.measure.value > rule.threshold;
        f.text = std::string(rule.name) + ": " + percentText(f.measure) + " (" + std::string(rule.meaning) +
                 "; a fault above " + formatNumber("%g", 100 * rule.threshold) + " %)";
        v.faults.push_back(std::move(f));
    }
    double score = 0, variance = 0;
    for (const ScoreWeight& w : kScoreWeights) {
        const ViewerFigure d = relativeDifference((figures.*findViewerFigure(w.figure)->get)(),
                                                  (reference.*findViewerFigure(w.figure)->get)());
        // The ratio in percent, or its balance min(r, 1 / r), whose error is the ratio's over r^2 above 1.
        double ratio = 100 + d.value, error = d.stderr;
        if (w.balanced && ratio > 100) {
            error *= 1e4 / (ratio * ratio);
            ratio = 1e4 / ratio;
        }
        score += w.weight * ratio;
        variance += w.weight * w.weight * error * error;
    }
    v.score = {score, std::sqrt(variance)};

    v.summary =
        "light performance " + formatWithError(v.score.value, v.score.stderr) + " (the GIA reference: 100)";
    std::string faults;
    for (const FaultFinding& f : v.faults)
        if (f.present) faults += (faults.empty() ? "" : ", ") + std::string(f.rule->name);
    v.summary += faults.empty() ? "; no faults" : "; faults: " + faults;
    return v;
}

nlohmann::json toJson(const ViewerFigures& figures, const Verdict& verdict, const ViewerSettings& settings) {
    const auto figure = [](const ViewerFigure& f) {
        return nlohmann::json{{"value", f.value}, {"stderr", f.stderr}};
    };
    nlohmann::json list = nlohmann::json::object();
    nlohmann::json sentences = nlohmann::json::array();
    for (const FigureComparison& c : verdict.figures) {
        list[std::string(c.info->key)] = {{"value", c.stone.value},
                                          {"stderr", c.stone.stderr},
                                          {"set_up", c.info->setUp},
                                          {"reference", c.reference.value},
                                          {"reference_stderr", c.reference.stderr},
                                          {"difference_pct", c.difference.value},
                                          {"difference_pct_stderr", c.difference.stderr}};
        sentences.push_back(c.text);
    }
    nlohmann::json faults = nlohmann::json::array();
    for (const FaultFinding& f : verdict.faults) {
        faults.push_back({{"key", f.rule->key},
                          {"name", f.rule->name},
                          {"meaning", f.rule->meaning},
                          {"measure", f.measure.value},
                          {"measure_stderr", f.measure.stderr},
                          {"threshold", f.rule->threshold},
                          {"applies", f.applies},
                          {"present", f.present},
                          {"text", f.text}});
    }
    return {{"settings", toJson(settings)},
            {"reference", verdict.reference},
            {"figures", list},
            {"faults", faults},
            {"score", figure(verdict.score)},
            {"verdict", {{"summary", verdict.summary}, {"figures", sentences}}},
            {"office", {{"points", figures.office.points}, {"rays", figures.office.rays}}},
            {"spot", {{"photons", figures.spot.photons}, {"hit", figures.spot.hit}}}};
}

nlohmann::json viewerReport(const Stone& stone, const TraceSettings& trace, RunControl* control) {
    if (!trace.viewer.enabled) return nullptr;
    const ViewerFigures figures = viewStone(stone, trace, control);
    if (figures.cancelled) throw Canceled();
    const ViewerFigures& reference = referenceFigures(trace, control);
    return toJson(figures, judge(stone, figures, reference), trace.viewer);
}

}  // namespace facetlight
