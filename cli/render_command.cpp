// facetlight render: trace a stone for the statistics, then render it and write the three pictures and the
// statistics into a folder.
#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "io/mesh_resolver.h"
#include "process_communicator.h"
#include "study/study.h"
#include "terminal_output.h"
#include "trace_options.h"
#include "util/error.h"

namespace facetlight::cli {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
    TraceOptions trace;
    RenderSettings render;
    std::string mapPhotons = std::to_string(RenderSettings{}.mapPhotons);
    std::string out = ".";
};

void run(RenderOptions& o) {
    StudySettings settings;
    settings.trace = toTraceSettings(o.trace);
    o.render.mapPhotons = parseCount(o.mapPhotons, "--map-photons", 1000, kMaxPhotons);
    o.render.validate();
    settings.render = o.render;
    const fs::path out(o.out);
    std::error_code ec;
    fs::create_directories(out, ec);
    if (ec || !fs::is_directory(out)) throw Error("cannot create the output folder '" + o.out + "'");
    const Stone stone = resolveStone(o.trace.mesh);

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

    writeFile(out / "render.png", result.renderPng);
    writeFile(out / "heatmap.png", result.heatmapPng);
    writeFile(out / "heatmap.json", result.heatmapLayout);
    writeFile(out / "angular.png", result.angularPng);
    writeFile(out / "stats.csv", result.statsCsv);
    writeFile(out / "stats.json", result.stats.dump(2) + "\n");
    std::cout << "wrote render.png, heatmap.png, heatmap.json, angular.png, stats.json, stats.csv to " << out.string()
              << " in " << seconds << " s\n";
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand(
        "render",
        "Trace a stone, render it with its caustics and write render.png, heatmap.png, angular.png, "
        "stats.json and stats.csv");
    addTraceOptions(cmd, o->trace);
    cmd->add_option("--width", o->render.width, "Image width in pixels")->capture_default_str();
    cmd->add_option("--height", o->render.height, "Image height in pixels")->capture_default_str();
    cmd->add_option("--samples", o->render.samples, "Samples per pixel (each on its own wavelength band)")
        ->capture_default_str();
    cmd->add_option("--max-depth", o->render.maxDepth, "Specular bounces followed from the camera")
        ->capture_default_str();
    cmd->add_option("--map-photons", o->mapPhotons, "Photons traced for the caustic map and the angular plot")
        ->capture_default_str();
    cmd->add_option("--elevation", o->render.camera.elevationDeg, "Camera elevation, degrees (90: face-up)")
        ->capture_default_str();
    cmd->add_option("--azimuth", o->render.camera.azimuthDeg, "Camera azimuth, degrees")
        ->capture_default_str();
    cmd->add_option("--distance", o->render.camera.distance, "Camera distance in girdle diameters")
        ->capture_default_str();
    cmd->add_option("--fov", o->render.camera.fovDeg, "Vertical field of view, degrees")
        ->capture_default_str();
    cmd->add_option("--out", o->out, "Folder for the pictures and statistics (created if missing)")
        ->capture_default_str();
    cmd->callback([o] { run(*o); });
}

}  // namespace facetlight::cli
