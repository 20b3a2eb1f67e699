#pragma once
// The whole service in one object, for main() and the tests: the stores (jobs, meshes, result files), the
// mesh catalog, the runner, the queue with its worker and the HTTP server, started and stopped in the right
// order.
#include <atomic>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <httplib.h>

#include "api.h"
#include "http_server.h"
#include "job_queue.h"
#include "job_spec.h"
#include "job_store.h"
#include "mesh_catalog.h"
#include "mesh_store.h"
#include "result_store.h"
#include "study_runner.h"

namespace facetlight::server {

struct ServiceConfig {
    std::filesystem::path dataDir = "data";
    std::filesystem::path meshesDir = "meshes";
    std::filesystem::path webDir = "web";
    // Debian's libjs-three, served at /vendor/three/ for the page's 3-D view (script_folder.h); missing: the
    // page says the view needs it.
    std::filesystem::path threeDir = "/usr/share/javascript/three";
    ServiceLimits limits;
    ConnectionLimits http;  // threads, per-peer connections, request deadline
    int cores = 0;          // 0: std::thread::hardware_concurrency()
    bool accessLog = true;
    // Names the server is reached by besides localhost, 127.0.0.1 and [::1] (--allowed-host): requests for
    // other Host names are refused.
    std::vector<std::string> allowedHosts;
    // The bearer token every /api request must carry (--token-file); empty: none is asked for.
    std::string token;
    std::optional<LaunchSettings> launch;  // run jobs through a launcher such as mpirun (docs/distributed.md)
    // For tests only: the rates jobs are estimated from, instead of this machine's measured ones (a test
    // makes a long job look short, to see it stopped over its budget).
    std::optional<CostRates> costRates;
};

class Service {
  public:
    // Opens the store, recovers its queue and starts the worker. Throws Error when the store cannot open.
    explicit Service(ServiceConfig config);
    ~Service();  // stop()

    // Binds; false (bind) or -1 (bindToAnyPort) when the address is taken.
    bool bind(const std::string& host, int port);
    int bindToAnyPort(const std::string& host);
    // Serves until stop(); blocks. Returns at once when stop() came first.
    bool listen();
    // Stops HTTP (waiting for listen() to be under way, so the stop is not lost), then the worker (the
    // running job goes back to the queue), and leaves the store to close with the object. Idempotent.
    void stop();

    JobStore& store() { return *store_; }
    JobQueue& queue() { return *queue_; }

  private:
    ServiceConfig config_;
    std::unique_ptr<Database> database_;
    std::unique_ptr<JobStore> store_;
    std::unique_ptr<MeshStore> meshes_;
    std::unique_ptr<ResultStore> results_;
    std::unique_ptr<MeshCatalog> catalog_;
    std::unique_ptr<StudyRunner> runner_;
    std::unique_ptr<JobQueue> queue_;
    std::unique_ptr<Api> api_;
    HttpServer http_;
    std::atomic<bool> listenStarted_{false}, listenEnded_{false}, stopped_{false};
};

}  // namespace facetlight::server
