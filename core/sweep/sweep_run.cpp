#include "sweep/sweep_run.h"

#include <algorithm>
#include <chrono>
#include <map>
#include <optional>

#include "scene/scene.h"
#include "stats/fire_stats.h"
#include "util/run_control.h"
#include "sweep/sweep_figures.h"
#include "sweep/sweep_files.h"
#include "trace/photon_tracer.h"
#include "util/error.h"
#include "util/parallel.h"
#include "viewer/verdict.h"

namespace facetlight {
namespace {

// A point's viewer figures and score, each with its `_stderr`; the reference it is scored against is traced
// once for each distinct set of settings (referenceFigures). Null when control cancels it.
nlohmann::json sweepViewerFigures(const Stone& stone, const TraceSettings& settings, RunControl* control) {
    const ViewerFigures figures = viewStone(stone, settings, control);
    if (figures.cancelled) return nullptr;
    const Verdict verdict = judge(stone, figures, referenceFigures(settings));
    nlohmann::json out = nlohmann::json::object();
    for (const FigureComparison& c : verdict.figures) {
        out[std::string(c.info->key)] = c.stone.value;
        out[std::string(c.info->key) + "_stderr"] = c.stone.stderr;
    }
    out["score"] = verdict.score.value;
    out["score_stderr"] = verdict.score.stderr;
    return out;
}

}  // namespace

SweepResult runSweep(const SweepPlan& plan, RunControl& control, const SweepPointHooks& hooks) {
    SerialCommunicator serial;
    return runSweep(plan, control, hooks, serial);
}

SweepResult runSweep(const SweepPlan& plan, RunControl& control, const SweepPointHooks& hooks,
                     Communicator& comm) {
    plan.validate();
    const auto start = std::chrono::steady_clock::now();
    SweepResult result{plan, sweepPoints(plan), 0};
    const CutShape& shape = plan.cutShape();
    const int threads = plan.trace.threads;
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
            // A point kept by a build that reported no fire, viewer or colour figures is traced again.
            const TraceSettings& t = result.points.at(k).trace;
            if (j.contains("totals") &&
                ((t.fire.enabled && !j.contains("fire")) || (t.viewer.enabled && !j.contains("viewer")) ||
                 (plan.colour && !j.contains("colour"))))
                continue;
            restoreSweepPoint(plan, j, result.points.at(k));
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
                stones[d] = Stone::build(shape.build(*designs[d]), plan.shape);
            } catch (const Error& e) {
                designError[d] = e.what();
            }
        }
        return uint64_t(0);
    });
    if (anyRank(comm, control.cancelled())) throw Canceled();

    // The reference the points' scores compare with, once, on every thread (not counted as progress).
    if (plan.trace.viewer.enabled) referenceFigures(plan.trace);
    // Several points at once; the threads left over trace within each (a trace's bits do not depend on them).
    // Progress counts photons, view rays and colour pixels, so that a cancel stops a point within a block of
    // them.
    const uint64_t pointUnits =
        plan.trace.photons + (plan.trace.viewer.enabled ? viewerUnits(plan.trace.viewer) : 0) +
        (plan.colour ? uint64_t(plan.colour->pictureSize) * uint64_t(plan.colour->pictureSize) : 0);
    control.startPhase(RunPhase::Tracing, mine.size() * pointUnits);
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
                    if (p.trace.viewer.enabled) {
                        p.viewer = sweepViewerFigures(*stone, settings, &control);
                        if (p.viewer.is_null()) return uint64_t(0);
                    }
                    // The colour view at the point's size and material, as a render's --colour sees it.
                    if (plan.colour) {
                        const ColourView view = colourView(*stone, settings, *plan.colour, &control);
                        if (view.cancelled) return uint64_t(0);
                        p.colour = sweepColourFigures(view);
                    }
                } catch (const Error& e) {
                    p.error = e.what();
                }
            }
            if (!p.ok()) control.advance(pointUnits);
            if (hooks.onPoint) hooks.onPoint(k, p);  // kept before it counts as done
            control.finishItem();
        }
        return uint64_t(0);
    });
    if (anyRank(comm, !finished || control.cancelled())) throw Canceled();

    if (comm.size() > 1) {
        nlohmann::json traced = nlohmann::json::object();
        for (const size_t k : mine) traced[std::to_string(k)] = sweepPointJson(plan, result.points[k]);
        for (const std::string& bytes : comm.allGather(traced.dump())) {
            const nlohmann::json points = nlohmann::json::parse(bytes);
            for (const auto& [key, j] : points.items()) {
                const size_t k = std::stoul(key);
                if (k % size_t(comm.size()) == size_t(comm.rank())) continue;
                restoreSweepPoint(plan, j, result.points.at(k));
                if (comm.isRoot() && hooks.onPoint) hooks.onPoint(k, result.points[k]);
            }
        }
    }
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    control.startPhase(RunPhase::Done, 0);
    return result;
}
}  // namespace facetlight
