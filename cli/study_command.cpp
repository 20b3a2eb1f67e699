// facetlight study: runs a study described by a JSON job file and writes its results into a folder. The
// service's launcher runs jobs this way as a child process, across MPI ranks under mpirun.
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "cuts/mesh_resolver.h"
#include "process_communicator.h"
#include "progress_json.h"
#include "result_folder.h"
#include "study/job_request.h"
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
    JobRequest spec;
    // The service's launcher writes the file from the job's typed request (its canonical JSON, toJson): this
    // process cannot share it, so reading it back here is the one parse it needs.
    nlohmann::json job = readJob(options.job);  // its errors name the file
    try {
        // Job files of earlier versions hold the trace settings under "trace", as scripts/same-results
        // writes them for both builds.
        if (job.is_object() && job.contains("trace") && job["trace"].is_object()) {
            const nlohmann::json trace = job["trace"];
            job.erase("trace");
            job.update(trace);
        }
        spec = JobRequest::fromJson(job);
    } catch (const Error& e) {
        throw Error(e.field(), "job file " + options.job + ": " + e.what());
    }
    const StudySettings& settings = spec.settings;
    const fs::path out(options.out);
    if (comm.isRoot()) {  // before the work, so that a folder we cannot make costs no trace
        std::error_code ec;
        fs::create_directories(out, ec);
        if (ec || !fs::is_directory(out)) throw Error("cannot create the output folder " + out.string());
    }

    RunControl control;
    StudyResult result;
    if (settings.sweep) {
        // The points are shared among the ranks; progress in this rank's photons, as a share of the round's.
        ProgressJson progress(options.progressJson && comm.isRoot(), control, [&](RunPhase phase) {
            return phase == RunPhase::Tracing ? control.itemsTotal() * settings.trace.photons : 0;
        });
        result = runSweepJob(spec.mesh, settings, control, comm);
    } else {
        Stone stone = spec.cut.empty() ? resolveStone(spec.mesh) : cutStone(spec, spec.mesh);
        if (!spec.name.empty()) stone.name = spec.name;
        ProgressJson progress(options.progressJson && comm.isRoot(), control,
                              [&](RunPhase phase) { return studyUnits(settings, phase); });
        result = runStudy(stone, settings, control, comm);
        if (comm.size() > 1) result.stats["timing"]["ranks"] = comm.size();
    }
    if (!comm.isRoot()) return;
    writeResultFiles(out, result);
}

}  // namespace

void addStudyCommand(CLI::App& app) {
    auto options = std::make_shared<StudyOptions>();
    CLI::App* cmd = app.add_subcommand(
        "study", "Run a job file's study into a folder (how the service runs jobs through a launcher)");
    cmd->add_option(
           "--job", options->job,
           "A file of the job's JSON, as POST /api/jobs takes it: {\"mesh\", \"name\", \"photons\", ..., "
           "\"render\": {...}}")
        ->required();
    cmd->add_option("--out", options->out,
                    "Folder for stats.json, stats.csv and the PNGs, created if missing (rank 0 writes)")
        ->required();
    cmd->add_flag("--progress-json", options->progressJson, "Write progress as JSON lines on stderr");
    cmd->callback([options] { runStudyCommand(*options); });
}

}  // namespace facetlight::cli
