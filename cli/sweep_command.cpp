// facetlight sweep: trace a shape of the cut library, a GemCad design or a mesh over a grid of one or two of
// its parameters (a design's tier angles) or trace settings, and write sweep.json, sweep.csv and the
// pictures into a folder.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.h"
#include "io/obj_writer.h"
#include "sweep/optimizer.h"
#include "sweep/sweep_job.h"
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
    std::vector<std::string> figures;  // none: defaultSweepFigure
    std::string out;
    std::string maximize;
    bool maximizeGiven = false;  // --maximize, maybe without a figure
    std::vector<std::string> constraints;
    int refineRounds = OptimizeSettings{}.refineRounds;
    TraceOptions trace;
    ViewFlags<ColourSettings> colour;
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

void runSweepCommand(const SweepOptions& o) {
    if (o.vary.empty())
        throw Error("sweep: say what to vary with --vary NAME=LO:HI:STEP (or NAME=V1,V2,...)");
    if (!o.maximizeGiven && !o.constraints.empty()) throw Error("--constraint applies to --maximize only");
    if (o.refineRounds < 0 || o.refineRounds > 6) throw Error("--refine-rounds must be between 0 and 6");
    SweepRequest request;
    for (const std::string& text : o.vary) request.axes.push_back(parseSweepAxis(text));
    request.set = fixedValues(o.set);
    const TraceSettings trace = toTraceSettings(o.trace);
    const std::optional<ColourSettings> colour = o.colour.read();
    request.figures = o.figures.empty() ? std::vector<std::string>{defaultSweepFigure(trace)} : o.figures;
    request.maximize = o.maximizeGiven && o.maximize.empty() ? defaultSweepFigure(trace) : o.maximize;
    request.constraints = o.constraints;
    request.refineRounds = o.refineRounds;
    checkSweepFigures(request, trace, colour.has_value(), {"--figure", "--maximize", "--constraint", false});
    // A library shape by name, else a design or mesh file (its tiers, or trace settings only, are the axes).
    const SweepPlan plan = planSweepOf(o.shape, request, trace, colour);
    const fs::path out(o.out);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw Error("cannot create the folder " + out.string() + ": " + ec.message());

    RunControl control;
    SerialCommunicator serial;
    SweepOutputs result;
    {
        ProgressLine bar(true, control);
        result = runSweepRequest(plan, request, control, serial);
    }
    writeFile(out / "sweep.csv", result.csv());
    writeFile(out / "sweep.json", result.json());
    for (const auto& [name, png] : result.pictures) writeFile(out / name, png);
    size_t failed = 0;
    for (const SweepPoint& p : result.sweep.points) failed += !p.ok();
    std::printf("wrote %s: %zu points in %.1f s", (out / "sweep.json").c_str(), result.sweep.points.size(),
                result.sweep.seconds);
    if (failed) std::printf(" (%zu could not be traced: see their \"error\")", failed);
    std::printf("\n");
    if (result.best.is_null()) return;

    writeTextFile((out / "best.obj").string(), result.bestObj);
    if (!result.bestAsc.empty()) writeTextFile((out / "best.asc").string(), result.bestAsc);
    writeFile(out / "best.json", result.best.dump(2) + "\n");
    const nlohmann::json& best = result.best["best"];
    std::printf("best %s %.4f +- %.4f (95%%: %.4f to %.4f) at",
                result.best["figure"].get<std::string>().c_str(), best["value"].get<double>(),
                best["stderr"].get<double>(), best["interval"][0].get<double>(),
                best["interval"][1].get<double>());
    for (const auto& [name, value] : best["values"].items())
        std::printf(" %s %g", name.c_str(), value.get<double>());
    const size_t ties = result.best["ties"].size();
    std::printf(" (%llu photons); %zu design%s cannot be told apart from it; wrote %s and %s%s%s\n",
                (unsigned long long)best["photons"].get<uint64_t>(), ties, ties == 1 ? "" : "s",
                (out / "best.json").c_str(), (out / "best.obj").c_str(), result.bestAsc.empty() ? "" : " and ",
                result.bestAsc.empty() ? "" : (out / "best.asc").c_str());
}

}  // namespace

void addSweepCommand(CLI::App& app) {
    auto o = std::make_shared<SweepOptions>();
    o->trace.defaults.photons = 200000;
    CLI::App* cmd = app.add_subcommand(
        "sweep",
        "Trace a shape of the cut library, a GemCad design or a mesh over a grid of its proportions (a "
        "design's tier angles, tier:NAME) or trace settings; write sweep.json and sweep.csv");
    cmd->add_option("shape", o->shape,
                    "Shape name (facetlight cut --list shows them), or a .asc design or mesh file")
        ->required();
    cmd->add_option(
           "--vary", o->vary,
           "NAME=LO:HI:STEP or NAME=V1,V2,...: a parameter of the shape (a design's tier:NAME slope), or "
           "tilt, head_shadow, material, light, n, size_mm, optic_axis_tilt, optic_axis_azimuth or "
           "optic_axis_rotation (a biaxial stone's); once or twice")
        ->take_all();
    cmd->add_option("--set", o->set,
                    "NAME=VALUE: a parameter of the shape held at a value other than its default")
        ->take_all();
    cmd->add_option("--figure", o->figures,
                    "Figures to draw: curves.png for one varied quantity, map_FIGURE.png for two (default " +
                        std::string(kDefaultSweepFigure) + ", with --no-view " +
                        kDefaultSweepFigureWithoutViewer + ")")
        ->take_all();
    cmd->add_option("--out", o->out, "Folder for sweep.json, sweep.csv and the pictures")->required();
    CLI::Option* maximize =
        cmd->add_option("--maximize", o->maximize,
                        "Search the varied parameters for the design with the highest FIGURE (default " +
                            std::string(kDefaultSweepFigure) + ", with --no-view " +
                            kDefaultSweepFigureWithoutViewer +
                            "): the sweep, then finer grids with more photons; writes best.json, best.obj and best.asc")
            ->expected(0, 1);
    cmd->add_option(
           "--constraint", o->constraints,
           "With --maximize: NAME<=VALUE or NAME>=VALUE, e.g. total_depth<=62 (a proportion in %, or a "
           "figure)")
        ->take_all();
    cmd->add_option("--refine-rounds", o->refineRounds,
                    "With --maximize: finer grids after the sweep, each with 4 times the photons")
        ->capture_default_str();
    addTraceOptions(cmd, o->trace, false);
    o->colour.add(
        cmd, "--colour",
        "Also measure every point's face-up colour (the colour figures colour_lightness, colour_a, "
        "colour_b, colour_chroma, colour_windowed, colour_extinct, colour_saturated; docs/optics.md) "
        "under a CIE illuminant, absorbing at the point's size",
        colourSettingsSchema(), "colour");
    cmd->callback([o, maximize] {
        o->maximizeGiven = maximize->count() > 0;
        runSweepCommand(*o);
    });
}

}  // namespace facetlight::cli
