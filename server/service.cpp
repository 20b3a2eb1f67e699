#include "service.h"

#include <chrono>
#include <iostream>
#include <thread>

#include "script_folder.h"
#include "util/number_text.h"

namespace facetlight::server {

Service::Service(ServiceConfig config) : config_(std::move(config)), http_(config_.http) {
    const int cores = config_.cores > 0 ? config_.cores : int(std::thread::hardware_concurrency());
    database_ = std::make_unique<Database>(config_.dataDir);
    store_ = std::make_unique<JobStore>(*database_);
    meshes_ =
        std::make_unique<MeshStore>(*database_, config_.dataDir / "meshes", config_.limits.maxMeshStoreBytes);
    results_ = std::make_unique<ResultStore>(config_.dataDir / "jobs");
    catalog_ = std::make_unique<MeshCatalog>(*meshes_, config_.meshesDir);
    runner_ = makeStudyRunner(*catalog_, config_.launch);
    const CostRates& rates = config_.costRates ? *config_.costRates : machineCostRates();
    const JobBudget budget(config_.limits.maxJobSeconds, rates);
    queue_ = std::make_unique<JobQueue>(*store_, *results_, *runner_, config_.limits.maxQueued,
                                        config_.limits.minFreeBytes, cores, budget);
    if (budget.maxSeconds() > 0) {
        std::cerr << "facetlight-server: jobs estimated over " << formatSeconds(budget.maxSeconds())
                  << " s are refused and stopped after " << formatSeconds(budget.runSeconds())
                  << " s (--max-job-seconds); a thread here traces "
                  << formatNumber("%.2g", 1 / rates.tracePhoton) << " photons/s and renders "
                  << formatNumber("%.2g", 1 / (rates.renderRay * RenderSettings{}.maxDepth))
                  << " samples/s\n";
    }
    const std::string& readOnly = database_->readOnlyReason();
    api_ = std::make_unique<Api>(*results_, *queue_, *catalog_, config_.limits, readOnly,
                                 config_.allowedHosts, config_.token);
    http_.set_tcp_nodelay(true);  // headers and body go out as two writes: no Nagle delay between them
    api_->install(http_, config_.accessLog);
    std::error_code ec;
    if (!config_.webDir.empty() && std::filesystem::is_directory(config_.webDir, ec)) {
        // The page's ES modules: JavaScript's media type (RFC 9239), which browsers require of module
        // scripts.
        http_.set_file_extension_and_mimetype_mapping("js", "text/javascript");
        http_.set_file_extension_and_mimetype_mapping("mjs", "text/javascript");
        if (!http_.set_mount_point("/", config_.webDir.string(), {{"Cache-Control", kStaticCacheControl}})) {
            std::cerr << "facetlight-server: cannot serve " << config_.webDir << "\n";
        }
    } else if (!config_.webDir.empty()) {
        std::cerr << "facetlight-server: no web page folder at " << config_.webDir
                  << "; serving the API only\n";
    }
    // Only .js files under build/ and examples/jsm/, where OrbitControls imports
    // '../../../build/three.module.js'.
    const ScriptFolder three{"/vendor/three/", config_.threeDir, {"build", "examples/jsm"}};
    if (!config_.threeDir.empty() && !serveScripts(http_, three)) {
        std::cerr << "facetlight-server: no three.js at " << config_.threeDir
                  << " (Debian's libjs-three, --three-js): the page's 3-D view is off\n";
    }
    // A full or read-only disk does not keep the service from starting: it says why here and in /healthz.
    if (!readOnly.empty()) {
        std::cerr << "facetlight-server: the store " << config_.dataDir << " is read-only (" << readOnly
                  << "): serving jobs and results, running and accepting none\n";
    } else if (const std::string shortage = results_->spaceShortage(config_.limits.minFreeBytes);
               !shortage.empty()) {
        std::cerr << "facetlight-server: " << shortage
                  << ": new jobs and uploads get 507 and queued jobs fail until space is freed\n";
    }
    queue_->start(readOnly.empty());
}

Service::~Service() {
    stop();
}

bool Service::bind(const std::string& host, int port) {
    return http_.bind(host, port);
}

int Service::bindToAnyPort(const std::string& host) {
    return http_.bindToAnyPort(host);
}

bool Service::listen() {
    listenStarted_ = true;
    if (stopped_) {
        listenEnded_ = true;
        return true;
    }
    const bool ok = http_.listen_after_bind();
    listenEnded_ = true;
    return ok;
}

void Service::stop() {
    if (stopped_.exchange(true)) return;
    if (listenStarted_) {
        // A stop() before the listening loop is running would be lost and listen() would never return.
        while (!http_.is_running() && !listenEnded_)
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        http_.stop();
    }
    queue_->stop();
}

}  // namespace facetlight::server
