// facetlight trace: shoot photons at a stone and print the per-facet light statistics as JSON.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <optional>
#include <thread>

#include "commands.h"
#include "distributed_trace.h"
#include "error.h"
#include "mesh_resolver.h"
#include "photon_tracer.h"
#include "process_communicator.h"
#include "progress_json.h"

namespace facetlight::cli {

namespace {

struct TraceOptions {
    std::string mesh;
    std::string photons = "1e6";
    int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    uint64_t seed = 1;
    std::string light = "collimated";
    double tilt = 0;
    double headShadow = 0;
    std::string material = "diamond";
    std::optional<double> n;
    bool noDispersion = false;
    int maxBounces = 64;
    std::string intersector = "auto";
    std::string jsonPath;
    std::string csvPath;
    bool progressJson = false;
};

// "1e6" and "1000000" alike; anything but a whole number in range is refused.
uint64_t parsePhotonCount(const std::string& text) {
    size_t used = 0;
    double v = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != text.size() || !(v >= 1 && v <= double(kMaxPhotons)) || v != std::floor(v)) {
        throw Error("--photons must be a whole number between 1 and 1e10 (got '" + text + "')");
    }
    return uint64_t(v);
}

// Redraws a one-line bar on stderr until `finished`.
void showProgress(const TraceControl& control, uint64_t total, const std::atomic<bool>& finished) {
    while (!finished.load()) {
        const double share = double(control.photonsDone.load()) / double(total);
        const int width = 40, filled = int(share * width);
        std::fprintf(stderr, "\r[%s%s] %5.1f%%", std::string(filled, '#').c_str(),
                     std::string(width - filled, ' ').c_str(), 100 * share);
        std::fflush(stderr);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    std::fprintf(stderr, "\r%*s\r", 50, "");
}

void writeFile(const std::string& path, const std::string& what,
               const std::function<void(std::ostream&)>& write) {
    std::ofstream out(path, std::ios::binary);
    if (!out) throw Error("cannot write " + what + " to '" + path + "'");
    write(out);
    if (!out.flush()) throw Error("cannot write " + what + " to '" + path + "'");
}

void run(const TraceOptions& o) {
    TraceSettings settings;
    settings.photons = parsePhotonCount(o.photons);
    settings.threads = o.threads;
    settings.seed = o.seed;
    settings.material = o.material;
    settings.n = o.n;
    settings.dispersion = !o.noDispersion;
    settings.maxBounces = o.maxBounces;
    settings.intersector = parseIntersector(o.intersector);
    settings.light.model = parseLightModel(o.light);
    settings.light.tiltDeg = o.tilt;
    settings.light.headShadowDeg = o.headShadow;
    settings.validate();

    const Stone stone = resolveStone(o.mesh);
    // Under mpirun the ranks split the blocks and rank 0 alone reports (docs/distributed.md).
    Communicator& comm = processCommunicator();
    const uint64_t local = localPhotons(comm, settings.photons);
    TraceControl control;
    std::atomic<bool> finished{false};
    std::thread bar;
    if (comm.isRoot() && !o.progressJson && isatty(STDERR_FILENO))
        bar = std::thread(showProgress, std::cref(control), local, std::cref(finished));
    TraceResult result;
    try {
        ProgressJson progress(o.progressJson && comm.isRoot(), [&] {
            return jobProgress("tracing", control.photonsDone, local, settings.photons);
        });
        result = traceDistributed(comm, stone, settings, &control);
    } catch (...) {
        finished = true;
        if (bar.joinable()) bar.join();
        throw;
    }
    finished = true;
    if (bar.joinable()) bar.join();

    if (!comm.isRoot()) return;
    nlohmann::json stats = statsToJson(result.stats, stone, settings, result.timing);
    if (comm.size() > 1) stats["timing"]["ranks"] = comm.size();
    const std::string json = stats.dump(2) + "\n";
    if (o.jsonPath.empty()) {
        std::cout << json;
    } else {
        writeFile(o.jsonPath, "the statistics", [&](std::ostream& out) { out << json; });
    }
    if (!o.csvPath.empty()) {
        writeFile(o.csvPath, "the facet table",
                  [&](std::ostream& out) { writeFacetCsv(out, result.stats, stone); });
    }
}

}  // namespace

void addTraceCommand(CLI::App& app) {
    auto o = std::make_shared<TraceOptions>();
    CLI::App* cmd =
        app.add_subcommand("trace", "Trace photons through a stone and report per-facet light statistics");
    cmd->add_option("--mesh", o->mesh, "OBJ, STL or GemCad .asc file, or a shipped shape name")->required();
    cmd->add_option("--photons", o->photons, "Photons to shoot, e.g. 1e6 or 1000000")->capture_default_str();
    cmd->add_option("--threads", o->threads, "Worker threads")->capture_default_str();
    cmd->add_option("--seed", o->seed, "Random seed; the same seed gives the same statistics")
        ->capture_default_str();
    cmd->add_option("--light", o->light, "collimated, hemisphere or point")->capture_default_str();
    cmd->add_option("--tilt", o->tilt, "Tilt of the stone about the x axis, degrees")->capture_default_str();
    cmd->add_option("--head-shadow", o->headShadow,
                    "Hemisphere: half-angle of the viewer's cone removed, degrees");
    cmd->add_option("--material", o->material, "diamond, cubic_zirconia, sapphire, fused_silica or bk7")
        ->capture_default_str();
    cmd->add_option("--n", o->n, "A constant refractive index instead of the material's");
    cmd->add_flag("--no-dispersion", o->noDispersion, "Trace every photon at 589.3 nm");
    cmd->add_option("--max-bounces", o->maxBounces, "Internal reflections before a photon counts as trapped")
        ->capture_default_str();
    cmd->add_option("--intersector", o->intersector, "auto, convex or embree")->capture_default_str();
    cmd->add_option("--json", o->jsonPath, "Write the statistics here instead of stdout");
    cmd->add_option("--csv", o->csvPath, "Also write the facet table as CSV here");
    cmd->add_flag("--progress-json", o->progressJson,
                  "Write progress as JSON lines on stderr (for a parent process)");
    cmd->callback([o] { run(*o); });
}

}  // namespace facetlight::cli
