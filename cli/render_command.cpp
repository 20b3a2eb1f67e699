// facetlight render: trace a stone for the statistics, then render it and write the three pictures and the
// statistics into a folder.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "cuts/mesh_resolver.h"
#include "process_communicator.h"
#include "result_folder.h"
#include "stats_summary.h"
#include "study/study.h"
#include "terminal_output.h"
#include "trace_options.h"
#include "util/error.h"

namespace facetlight::cli {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
    TraceOptions trace;
    SettingsFlags render;
    std::string out = ".";
    ViewFlags<AsetSettings> aset;
    SettingsFlags tiltFlags;
    ViewFlags<FirePictureSettings> firePicture;
    ViewFlags<ColourSettings> colour;
};

void run(RenderOptions& o) {
    StudySettings settings;
    settings.trace = toTraceSettings(o.trace);
    settings.render.emplace();
    o.render.apply(renderSettingsSchema(), *settings.render);
    settings.aset = o.aset.read();
    settings.firePicture = o.firePicture.read();
    settings.colour = o.colour.read();
    if (o.tiltFlags.given()) {
        settings.tiltSeries.emplace();
        o.tiltFlags.apply(tiltSeriesSettingsSchema(), *settings.tiltSeries);
    }
    const fs::path out(o.out);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out)) throw Error("cannot create the output folder '" + o.out + "'");
    const Stone stone = resolveStone(o.trace.mesh, stoneOptions(o.trace));

    RunControl control;
    // Under mpirun the ranks split the photons and the tiles; rank 0 writes (docs/distributed.md).
    Communicator& comm = processCommunicator();
    StudyResult result;
    const auto start = std::chrono::steady_clock::now();
    {
        ProgressLine bar(comm.isRoot(), control);
        result = runStudy(stone, settings, control, comm);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!comm.isRoot()) return;
    if (comm.size() > 1) result.stats["timing"]["ranks"] = comm.size();

    printStatsSummary(std::cout, result.stats);
    if (settings.aset) printAsetShares(std::cout, result.stats["aset"]);
    if (settings.colour) printColourFigures(std::cout, result.stats["colour"]);
    if (settings.tiltSeries) {
        const nlohmann::json& t = result.stats["tilt_series"];
        std::printf("tilt series: %zu frames, scintillation %.2f%% +- %.2f per frame\n", t["frames"].size(),
                    100 * t["scintillation"].get<double>(), 100 * t["scintillation_stderr"].get<double>());
    }
    std::cout << "wrote " << writeResultFiles(out, result) << " to " << out.string() << " in " << seconds
              << " s\n";
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "Trace a stone, render it with its caustics and write render.png, heatmap.png, angular.png, "
        "stats.json and stats.csv");
    addTraceOptions(cmd, o->trace);
    o->render.add(cmd, renderSettingsSchema().fields(), toJson(RenderSettings{}), "render");
    o->aset.add(cmd, "--aset",
                "Also write aset.png: each pixel coloured by where its light comes from (docs/physics.md)",
                asetSettingsSchema(), "aset");
    o->tiltFlags.add(cmd, tiltSeriesSettingsSchema().fields(), toJson(TiltSeriesSettings{}), "tilt_series");
    o->firePicture.add(cmd, "--fire-picture",
                       "Also write fire.png: the stone under a small bright light in spectral colour, its "
                       "flashes of fire (docs/physics.md)",
                       firePictureSettingsSchema(), "fire_picture");
    o->colour.add(cmd, "--colour",
                  "Also write colour.png: the stone face-up in true colour under a CIE illuminant, absorbing "
                  "at its size (docs/optics.md), and stats colour",
                  colourSettingsSchema(), "colour");
    cmd->add_option("--out", o->out, "Folder for the pictures and statistics (created if missing)")
        ->capture_default_str();
    cmd->callback([o] { run(*o); });
}

}  // namespace facetlight::cli
