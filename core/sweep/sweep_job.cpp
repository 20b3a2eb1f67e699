#include "sweep/sweep_job.h"

#include "cuts/cut_library.h"
#include "cuts/facet_design.h"
#include "io/gemcad_writer.h"
#include "io/obj_writer.h"
#include "image/image.h"
#include "sweep/optimizer.h"
#include "sweep/sweep_pictures.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;

json designJson(const std::vector<SweepAxis>& axes, const RatedDesign& d, double z) {
    json values = json::object();
    for (size_t a = 0; a < axes.size(); ++a) values[axes[a].name] = d.values[a];
    return {{"values", values},
            {"value", d.estimate.value},
            {"stderr", d.estimate.sigma},
            {"interval", {d.estimate.value - z * d.estimate.sigma, d.estimate.value + z * d.estimate.sigma}}};
}

}  // namespace

SweepOutputs runSweepRequest(const SweepPlan& plan, const SweepRequest& request, RunControl& control,
                             Communicator& comm, const SweepCheckpoint& checkpoint) {
    const int rounds = request.rounds();
    const bool keep = comm.isRoot() && checkpoint.store;
    const SweepRoundHooks hooks = [&](size_t round, const SweepPlan& s) {
        control.startStage(int(round) + 1, rounds, s.pointCount());
        SweepPointHooks h;
        if (checkpoint.restore)
            h.restore = [&checkpoint, round](size_t k) { return checkpoint.restore(round, k); };
        if (keep)
            h.onPoint = [&checkpoint, round, s](size_t k, const SweepPoint& p) {
                checkpoint.store(round, k, sweepPointJson(s, p));
            };
        return h;
    };
    SweepOutputs out;
    std::optional<OptimizeResult> best;
    OptimizeSettings settings;
    settings.refineRounds = request.refineRounds;
    std::vector<SweepResult> results;
    if (request.maximize.empty()) {
        out.sweep = runSweep(plan, control, hooks(0, plan), comm);
    } else {
        std::vector<SweepConstraint> constraints;
        for (const std::string& text : request.constraints) constraints.push_back(parseSweepConstraint(text));
        best = maximize(plan.axes, plan.trace.photons,
                        sweepObjective(plan, request.maximize, constraints, control, results, comm, hooks),
                        settings);
        out.sweep = results.front();
    }
    if (!comm.isRoot()) return out;
    size_t failed = 0;
    for (const SweepPoint& p : out.sweep.points) failed += !p.ok();
    if (failed == out.sweep.points.size())
        throw Error("no point of the sweep could be traced: " + out.sweep.points[0].error);
    for (const auto& [name, image] : sweepPictures(out.sweep, request.figures))
        out.pictures.emplace_back(name, encodePng(image));
    if (!best) return out;

    SweepPlan bestPlan = plan;
    for (size_t a = 0; a < plan.axes.size(); ++a) bestPlan.axes[a].values = {best->best.values[a]};
    const CutShape& shape = plan.cutShape();
    const CutValues cut = sweepPoints(bestPlan)[0].cut;
    const std::string command = plan.file ? "" : "facetlight cut " + cutCommandLine(shape, cut);
    out.bestObj = objText(shape.build(cut), command);
    // As GemCad .asc: a design's tiers as tweaked; a library shape's (or a convex mesh's) facet planes.
    std::string tweaked;
    for (const auto& [name, value] : cut) tweaked += " " + name + " " + formatNumber(value);
    GemCadDesign design;
    if (plan.file && plan.file->design) {
        design = plan.file->designAt(cut);
    } else if (const Stone stone = Stone::build(shape.build(cut), plan.shape); stone.convex) {
        design = gemCadDesignOf(stone);
    }
    if (!design.tiers.empty()) {
        design.headers.push_back("facetlight's best " + request.maximize + ":" + tweaked);
        out.bestAsc = writeGemCad(design);
    }

    json ties = json::array();
    for (const RatedDesign& t : best->ties) ties.push_back(designJson(best->lastAxes, t, settings.z));
    json roundsJson = json::array();
    for (const SweepResult& r : results) {
        json axes = json::object();
        for (const SweepAxis& a : r.plan.axes) axes[a.name] = a.values;
        roundsJson.push_back({{"photons", r.plan.trace.photons}, {"axes", axes}, {"seconds", r.seconds}});
    }
    json bestJson = designJson(best->lastAxes, best->best, settings.z);
    bestJson["photons"] = best->photons;
    bestJson["cut"] = cut;
    if (!command.empty()) bestJson["command"] = command;
    out.best = {{"figure", request.maximize},
                {"confidence", 0.95},
                {"constraints", request.constraints},
                {"best", bestJson},
                {"ties", ties},
                {"rounds", roundsJson},
                {"evaluations", best->evaluations}};
    return out;
}

}  // namespace facetlight
