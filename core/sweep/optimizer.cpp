#include "sweep/optimizer.h"

#include <algorithm>
#include <cmath>

#include "sweep/sweep_figures.h"
#include "util/error.h"
#include "util/excerpt.h"
#include "util/number_text.h"

namespace facetlight {
namespace {

std::vector<double> valuesAt(const std::vector<SweepAxis>& axes, size_t k) {
    std::vector<double> values(axes.size());
    for (size_t a = axes.size(); a-- > 0;) {
        values[a] = axes[a].values[k % axes[a].size()];
        k /= axes[a].size();
    }
    return values;
}

size_t highestFeasible(const std::vector<DesignEstimate>& estimates) {
    size_t best = estimates.size();
    for (size_t k = 0; k < estimates.size(); ++k)
        if (estimates[k].feasible && (best == estimates.size() || estimates[k].value > estimates[best].value))
            best = k;
    if (best == estimates.size()) throw Error("no design of the grid could be traced within the constraints");
    return best;
}

// The smallest gap between an axis's values (0 for a single value: that axis stays where it is).
double spacing(const SweepAxis& axis) {
    std::vector<double> v = axis.values;
    std::sort(v.begin(), v.end());
    double gap = 0;
    for (size_t i = 1; i < v.size(); ++i)
        if (v[i] > v[i - 1] && (gap == 0 || v[i] - v[i - 1] < gap)) gap = v[i] - v[i - 1];
    return gap;
}

const std::vector<std::string> kProportions{"total_depth", "crown_height", "pavilion_depth", "girdle",
                                            "table"};

}  // namespace

OptimizeResult maximize(const std::vector<SweepAxis>& coarse, uint64_t photons,
                        const GridObjective& objective, const OptimizeSettings& settings) {
    for (const SweepAxis& a : coarse)
        if (!a.numeric()) throw Error("the best design is searched over numbers; " + a.name + " takes names");
    OptimizeResult result;
    result.lastAxes = coarse;
    result.photons = photons;
    std::vector<DesignEstimate> estimates = objective(coarse, photons);
    result.evaluations = estimates.size();
    size_t best = highestFeasible(estimates);
    std::vector<double> step(coarse.size());
    for (size_t a = 0; a < coarse.size(); ++a) step[a] = spacing(coarse[a]);

    for (int round = 0; round < settings.refineRounds; ++round) {
        const std::vector<double> centre = valuesAt(result.lastAxes, best);
        std::vector<SweepAxis> axes = coarse;
        for (size_t a = 0; a < axes.size(); ++a) {
            step[a] /= 2;
            const auto [lo, hi] = std::minmax_element(coarse[a].values.begin(), coarse[a].values.end());
            axes[a].values.clear();
            for (int k = -settings.refineSteps; k <= settings.refineSteps; ++k) {
                const double v = std::round((centre[a] + k * step[a]) * 1e9) / 1e9;
                if (v >= *lo - 1e-9 && v <= *hi + 1e-9 &&
                    (axes[a].values.empty() || v > axes[a].values.back()))
                    axes[a].values.push_back(v);
            }
        }
        result.photons = std::min<uint64_t>(result.photons * settings.photonGrowth, kMaxPhotons);
        estimates = objective(axes, result.photons);
        result.evaluations += estimates.size();
        best = highestFeasible(estimates);
        result.lastAxes = std::move(axes);
    }

    result.best = {valuesAt(result.lastAxes, best), estimates[best]};
    const DesignEstimate& b = estimates[best];
    for (size_t k = 0; k < estimates.size(); ++k) {
        const DesignEstimate& e = estimates[k];
        if (k != best && e.feasible &&
            b.value - e.value <= settings.z * std::sqrt(b.sigma * b.sigma + e.sigma * e.sigma))
            result.ties.push_back({valuesAt(result.lastAxes, k), e});
    }
    return result;
}

bool SweepConstraint::holds(const SweepPoint& point) const {
    if (!point.ok()) return false;
    const nlohmann::json& source =
        point.proportions.contains(quantity) ? point.proportions : point.figures(quantity);
    if (!source.contains(quantity) || !source[quantity].is_number()) return false;
    const double v = source[quantity].get<double>();
    return atMost ? v <= limit : v >= limit;
}

SweepConstraint parseSweepConstraint(const std::string& text) {
    size_t at = text.find("<=");
    const bool atMost = at != std::string::npos;
    if (!atMost) at = text.find(">=");
    SweepConstraint c;
    if (at == std::string::npos || at == 0 || !parseNumber(text.substr(at + 2), c.limit))
        throw Error("constraint " + inQuotes(text) +
                    ": write NAME<=VALUE or NAME>=VALUE, e.g. total_depth<=62");
    c.atMost = atMost;
    std::string name = text.substr(0, at);
    if (name.size() > 4 && name.compare(name.size() - 4, 4, "_pct") == 0) name.resize(name.size() - 4);
    if (std::find(kProportions.begin(), kProportions.end(), name) != kProportions.end()) {
        c.quantity = name + "_pct";
        return c;
    }
    const auto& figures = sweepFigureNames();
    if (std::find(figures.begin(), figures.end(), name) == figures.end()) {
        std::string names;
        for (const std::string& n : kProportions) names += n + ", ";
        for (const std::string& n : figures) names += n + (n == figures.back() ? "" : ", ");
        throw Error("constraint " + inQuotes(text) + ": no quantity " + inQuotes(name) +
                    "; the quantities are: " + names);
    }
    c.quantity = name;
    return c;
}

TraceSettings searchRoundTrace(const TraceSettings& base, uint64_t photons) {
    TraceSettings round = base;
    round.photons = photons;
    // The viewer's samples grow with the photons, round by round.
    const double growth = double(photons) / double(base.photons);
    ViewerSettings& viewer = round.viewer;
    viewer.office.points = std::min(kMaxViewerPoints, uint64_t(double(viewer.office.points) * growth));
    viewer.spot.photons = std::min(kMaxViewerPhotons, uint64_t(double(viewer.spot.photons) * growth));
    return round;
}

GridObjective sweepObjective(const SweepPlan& base, const std::string& figure,
                             const std::vector<SweepConstraint>& constraints, RunControl& control,
                             std::vector<SweepResult>& rounds, Communicator& comm,
                             const SweepRoundHooks& hooks) {
    checkSweepFigure(figure, base.trace, base.colour.has_value());
    return [base, figure, constraints, &control, &rounds, &comm, hooks](const std::vector<SweepAxis>& axes,
                                                                        uint64_t photons) {
        SweepPlan plan = base;
        plan.axes = axes;
        plan.trace = searchRoundTrace(base.trace, photons);
        rounds.push_back(
            runSweep(plan, control, hooks ? hooks(rounds.size(), plan) : SweepPointHooks{}, comm));
        std::vector<DesignEstimate> out;
        for (const SweepPoint& p : rounds.back().points) {
            DesignEstimate e;
            e.feasible = p.ok() && std::all_of(constraints.begin(), constraints.end(),
                                               [&](const SweepConstraint& c) { return c.holds(p); });
            if (p.ok()) e.value = p.figure(figure), e.sigma = p.stderrOf(figure);
            out.push_back(e);
        }
        return out;
    };
}

}  // namespace facetlight
