// facetlight sweep: trace a shape of the cut library over a grid of one or two of its parameters (or trace
// settings) and write sweep.json, sweep.csv and the pictures into a folder.
#include <cstdio>
#include <filesystem>
#include <memory>

#include "commands.h"
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
    const fs::path out(o.out);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec) throw Error("cannot create the folder " + out.string() + ": " + ec.message());

    RunControl control;
    SweepResult result;
    {
        ProgressLine bar(true, control);
        result = runSweep(spec, control);
    }
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

}  // namespace

void addSweepCommand(CLI::App& app) {
    auto o = std::make_shared<SweepOptions>();
    o->trace.photons = "2e5";
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
    addTraceOptions(cmd, o->trace, false);
    cmd->callback([o] { runSweepCommand(*o); });
}

}  // namespace facetlight::cli
