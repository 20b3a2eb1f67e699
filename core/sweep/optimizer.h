#pragma once
// Finding the best design: a coarse sweep over the given grid, then rounds of finer grids around the best
// point so far, each with more photons a point. The objective is pluggable (a sweep's figure, or an analytic
// function in the tests).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "sweep/sweep_run.h"

namespace facetlight {

struct DesignEstimate {
    double value = 0, sigma = 0;  // the figure and its standard error
    bool feasible = true;         // traced, and within the constraints
};

// Evaluates every point of the grid the axes span (the sweep's point order: the first axis varies slowest)
// with `photons` photons a point.
using GridObjective =
    std::function<std::vector<DesignEstimate>(const std::vector<SweepAxis>& axes, uint64_t photons)>;

struct OptimizeSettings {
    int refineRounds = 3;       // finer grids after the coarse one
    int refineSteps = 2;        // each refined grid reaches this many of its steps either side of the best
    uint64_t photonGrowth = 4;  // each round traces this many times the photons of the round before
    double z = 1.96;            // the confidence interval, and the ties, in standard errors (95 %)
};

struct RatedDesign {
    std::vector<double> values;  // one per axis
    DesignEstimate estimate;
};

struct OptimizeResult {
    RatedDesign best;               // the highest of the last round
    uint64_t photons = 0;           // a point, in the last round
    std::vector<RatedDesign> ties;  // the last round's other designs it cannot be told apart from
    std::vector<SweepAxis> lastAxes;
    size_t evaluations = 0;  // points evaluated over all rounds
};

// Maximises the objective over numeric axes, starting from their grid and refining within the span of each
// (steps halved each round). Throws Error when an axis is not numeric or no point of a round is feasible.
OptimizeResult maximize(const std::vector<SweepAxis>& coarse, uint64_t photons,
                        const GridObjective& objective, const OptimizeSettings& settings = {});

// A limit on a point's trade proportion (e.g. "total_depth<=62", "%" figures from the statistics' `mesh`)
// or figure ("leakage<=0.1").
struct SweepConstraint {
    std::string quantity;  // a key of the point's proportions or totals
    bool atMost = true;
    double limit = 0;
    bool holds(const SweepPoint& point) const;
};
// "NAME<=VALUE" or "NAME>=VALUE"; NAME a proportion (total_depth, crown_height, pavilion_depth, girdle,
// table;
// "_pct" may be added) or a figure. Throws Error otherwise.
SweepConstraint parseSweepConstraint(const std::string& text);

// A search round's trace settings: `base`'s with `photons` photons a point, and the viewer's samples (office
// points, lamp photons) grown in the same proportion as the photons, within their limits.
TraceSettings searchRoundTrace(const TraceSettings& base, uint64_t photons);

// The objective of a sweep: `figure` at each point of `base` with the grid's axes and photons, infeasible
// where the point could not be traced or breaks a constraint. Each round's result is appended to `rounds`;
// each round runs on every rank of `comm` with the hooks `hooks` gives for it (its index from 0, its plan).
using SweepRoundHooks = std::function<SweepPointHooks(size_t round, const SweepPlan& plan)>;
GridObjective sweepObjective(const SweepPlan& base, const std::string& figure,
                             const std::vector<SweepConstraint>& constraints, RunControl& control,
                             std::vector<SweepResult>& rounds, Communicator& comm,
                             const SweepRoundHooks& hooks = {});

}  // namespace facetlight
