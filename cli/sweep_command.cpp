// facetlight sweep: trace a shape of the cut library over a grid of one or two of its parameters (or trace
// settings) and write sweep.json, sweep.csv and the pictures into a folder.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.h"
#include "io/obj_writer.h"
#include "study/optimizer.h"
#include "study/sweep.h"
#include "study/sweep_pictures.h"
#include "terminal_output.h"
#include "trace_options.h"
#include "util/error.h"
#include "util/number_text.h"

namespace facetlight::cli {
namespace {

namespace fs = std::filesystem;

struct SweepOptions {
    std::string shape;
    std::vector<std::string> vary;
    std::vector<std::string> set;
    std::vector<std::string> figures{"weighted_return"};
    std::string out;
    std::string maximize;
    std::vector<std::string> constraints;
    int refineRounds = OptimizeSettings{}.refineRounds;
    TraceOptions trace;
};

CutValues fixedValues(const std::vector<std::string>& settings) {
    CutValues values;
    for (const std::string& text : settings) {
        const size_t eq = text.find('=');
        double v = 0;
        if (eq == std::string::npos || eq == 0 || !parseNumber(text.substr(eq + 1), v))
            throw Error("--set '" + text + "': write NAME=VALUE, e.g. --set table=55");
        values[text.substr(0, eq)] = v;
    }
    return values;
}

// sweep.json, sweep.csv and the pictures; throws Error when no point could be traced.
void writeSweep(const SweepOptions& o, const SweepResult& result, const fs::path& out) {
    size_t failed = 0;
    for (const SweepPoint& p : result.points) failed += !p.ok();
    if (failed == result.points.size())
        throw Error("no point of the sweep could be traced: " + result.points[0].error);
    writeFile(out / "sweep.csv", sweepCsv(result));
    writeFile(out / "sweep.json", sweepToJson(result).dump(2) + "\n");
    for (const auto& [name, image] : sweepPictures(result, o.figures))
        writeFile(out / name, encodePng(image));
    std::printf("wrote %s: %zu points in %.1f s", (out / "sweep.json").c_str(), result.points.size(),
                result.seconds);
    if (failed) std::printf(" (%zu could not be traced: see their \"error\")", failed);
    std::printf("\n");
}

nlohmann::json designJson(const std::vector<SweepAxis>& axes, const RatedDesign& d, double z) {
    nlohmann::json values = nlohmann::json::object();
    for (size_t a = 0; a < axes.size(); ++a) values[axes[a].name] = d.values[a];
    return {{"values", values},
            {"value", d.estimate.value},
            {"stderr", d.estimate.sigma},
            {"interval", {d.estimate.value - z * d.estimate.sigma, d.estimate.value + z * d.estimate.sigma}}};
}

// --maximize: the coarse sweep written as usual, then refined rounds; best.json and best.obj.
void searchBest(const SweepOptions& o, const SweepSpec& spec, RunControl& control, const fs::path& out) {
    std::vector<SweepConstraint> constraints;
    for (const std::string& text : o.constraints) constraints.push_back(parseSweepConstraint(text));
    if (o.refineRounds < 0 || o.refineRounds > 6) throw Error("--refine-rounds must be between 0 and 6");
    OptimizeSettings settings;
    settings.refineRounds = o.refineRounds;
    std::vector<SweepResult> rounds;
    const OptimizeResult best =
        maximize(spec.axes, spec.trace.photons,
                 sweepObjective(spec, o.maximize, constraints, control, rounds), settings);
    writeSweep(o, rounds.front(), out);

    SweepSpec bestSpec = spec;
    for (size_t a = 0; a < spec.axes.size(); ++a) bestSpec.axes[a].values = {best.best.values[a]};
    const CutShape& shape = findCutShape(spec.shape);
    const CutValues cut = sweepPoints(bestSpec)[0].cut;
    const std::string command = cutCommandLine(shape, cut);
    writeTextFile((out / "best.obj").string(), objText(shape.build(cut), "facetlight cut " + command));

    nlohmann::json ties = nlohmann::json::array();
    for (const RatedDesign& t : best.ties) ties.push_back(designJson(best.lastAxes, t, settings.z));
    nlohmann::json limits = nlohmann::json::array();
    for (const std::string& text : o.constraints) limits.push_back(text);
    nlohmann::json roundsJson = nlohmann::json::array();
    for (const SweepResult& r : rounds) {
        nlohmann::json axes = nlohmann::json::object();
        for (const SweepAxis& a : r.spec.axes) axes[a.name] = a.values;
        roundsJson.push_back({{"photons", r.spec.trace.photons}, {"axes", axes}, {"seconds", r.seconds}});
    }
    nlohmann::json bestJson = designJson(best.lastAxes, best.best, settings.z);
    bestJson["photons"] = best.photons;
    bestJson["cut"] = cut;
    bestJson["command"] = "facetlight cut " + command;
    const nlohmann::json report = {
        {"figure", o.maximize}, {"confidence", 0.95},   {"constraints", limits},          {"best", bestJson},
        {"ties", ties},         {"rounds", roundsJson}, {"evaluations", best.evaluations}};
    writeFile(out / "best.json", report.dump(2) + "\n");
    std::printf("best %s %.4f +- %.4f (95%%: %.4f to %.4f) at", o.maximize.c_str(), best.best.estimate.value,
                best.best.estimate.sigma, bestJson["interval"][0].get<double>(),
                bestJson["interval"][1].get<double>());
    for (size_t a = 0; a < spec.axes.size(); ++a)
        std::printf(" %s %g", spec.axes[a].name.c_str(), best.best.values[a]);
    std::printf(" (%llu photons); %zu designs cannot be told apart from it; wrote %s and %s\n",
                (unsigned long long)best.photons, best.ties.size(), (out / "best.json").c_str(),
                (out / "best.obj").c_str());
}

void runSweepCommand(const SweepOptions& o) {
    if (o.vary.empty())
        throw Error("sweep: say what to vary with --vary NAME=LO:HI:STEP (or NAME=V1,V2,...)");
    SweepSpec spec;
    spec.shape = o.shape;
    spec.fixed = fixedValues(o.set);
    for (const std::string& text : o.vary) spec.axes.push_back(parseSweepAxis(text));
    spec.trace = toTraceSettings(o.trace);
    spec.validate();
    for (const std::string& f : o.figures) checkSweepFigure(f);
    if (!o.maximize.empty()) checkSweepFigure(o.maximize);
    if (o.maximize.empty() && !o.constraints.empty()) throw Error("--constraint applies to --maximize only");
    const fs::path out(o.out);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw Error("cannot create the folder " + out.string() + ": " + ec.message());

    RunControl control;
    ProgressLine bar(true, control);
    if (o.maximize.empty()) return writeSweep(o, runSweep(spec, control), out);
    searchBest(o, spec, control, out);
}

}  // namespace

void addSweepCommand(CLI::App& app) {
    auto o = std::make_shared<SweepOptions>();
    o->trace.defaults.photons = 200000;
    CLI::App* cmd = app.add_subcommand(
        "sweep",
        "Trace a shape of the cut library over a grid of its proportions; write sweep.json and sweep.csv");
    cmd->add_option("shape", o->shape, "Shape name (facetlight cut --list shows them)")->required();
    cmd->add_option(
           "--vary", o->vary,
           "NAME=LO:HI:STEP or NAME=V1,V2,...: a parameter of the shape, or tilt, head_shadow, material "
           "or light; once or twice")
        ->take_all();
    cmd->add_option("--set", o->set,
                    "NAME=VALUE: a parameter of the shape held at a value other than its default")
        ->take_all();
    cmd->add_option("--figure", o->figures,
                    "Figures to draw: curves.png for one varied quantity, map_FIGURE.png for two")
        ->take_all()
        ->capture_default_str();
    cmd->add_option("--out", o->out, "Folder for sweep.json, sweep.csv and the pictures")->required();
    cmd->add_option(
        "--maximize", o->maximize,
        "Search the varied parameters for the design with the highest FIGURE: the sweep, then finer "
        "grids with more photons; writes best.json and best.obj");
    cmd->add_option(
           "--constraint", o->constraints,
           "With --maximize: NAME<=VALUE or NAME>=VALUE, e.g. total_depth<=62 (a proportion in %, or a "
           "figure)")
        ->take_all();
    cmd->add_option("--refine-rounds", o->refineRounds,
                    "With --maximize: finer grids after the sweep, each with 4 times the photons")
        ->capture_default_str();
    addTraceOptions(cmd, o->trace, false);
    cmd->callback([o] { runSweepCommand(*o); });
}

}  // namespace facetlight::cli
