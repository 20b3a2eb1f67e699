// facetlight study: runs a study described by a JSON job file and writes its results into a folder. The
// service's launcher runs jobs this way as a child process, across MPI ranks under mpirun.
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "io/mesh_resolver.h"
#include "process_communicator.h"
#include "progress_json.h"
#include "study/study.h"
#include "terminal_output.h"
#include "util/bounded_read.h"
#include "util/error.h"
#include "util/json_text.h"

namespace facetlight::cli {
namespace {

namespace fs = std::filesystem;

struct StudyOptions {
    std::string job;
    std::string out;
    bool progressJson = false;
};

// A job file is a few hundred bytes; the cap is the service's default body limit.
constexpr size_t kMaxJobFileBytes = 1 << 20;

nlohmann::json readJob(const std::string& path) {
    return parseUntrustedJson(readFileUpTo(path, kMaxJobFileBytes, "job file"), "job file " + path);
}

void runStudyCommand(const StudyOptions& options) {
    Communicator& comm = processCommunicator();
    const nlohmann::json job = readJob(options.job);
    if (!job.is_object() || !job.contains("mesh") || !job["mesh"].is_string())
        throw Error("job file " + options.job + ": \"mesh\" must be a string");
    StudySettings settings;
    settings.trace = TraceSettings::fromJson(job.value("trace", nlohmann::json::object()));
    if (job.contains("render")) settings.render = RenderSettings::fromJson(job["render"]);
    Stone stone = resolveStone(job["mesh"].get<std::string>());
    if (job.contains("name") && job["name"].is_string()) stone.name = job["name"];

    RunControl control;
    StudyResult result;
    {
        ProgressJson progress(options.progressJson && comm.isRoot(), control,
                              [&](RunPhase phase) { return studyUnits(settings, phase); });
        result = runStudy(stone, settings, control, comm);
    }
    if (!comm.isRoot()) return;
    if (comm.size() > 1) result.stats["timing"]["ranks"] = comm.size();
    const fs::path out(options.out);
    // stats.json last: its presence tells the launcher the folder is complete.
    writeFile(out / "stats.csv", result.statsCsv);
    // A trace-only study still has its heat-map; the render and the angular plot come with a render.
    for (const auto& [name, bytes] : {std::pair{"render.png", &result.renderPng},
                                      std::pair{"heatmap.png", &result.heatmapPng},
                                      std::pair{"heatmap.json", &result.heatmapLayout},
                                      std::pair{"angular.png", &result.angularPng}})
        if (!bytes->empty()) writeFile(out / name, *bytes);
    writeFile(out / "stats.json", result.stats.dump(2));
}

}  // namespace

void addStudyCommand(CLI::App& app) {
    auto options = std::make_shared<StudyOptions>();
    CLI::App* cmd = app.add_subcommand(
        "study", "Run a job file's study into a folder (how the service runs jobs through a launcher)");
    cmd->add_option("--job", options->job, "JSON: {\"mesh\", \"name\", \"trace\": {...}, \"render\": {...}}")
        ->required();
    cmd->add_option("--out", options->out, "Folder for stats.json, stats.csv and the PNGs (rank 0 writes)")
        ->required();
    cmd->add_flag("--progress-json", options->progressJson, "Write progress as JSON lines on stderr");
    cmd->callback([options] { runStudyCommand(*options); });
}

}  // namespace facetlight::cli
