// facetlight-server: the render service. Binds loopback unless told otherwise; SIGINT/SIGTERM stop HTTP,
// hand the running job back to the queue and close the store.
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <iostream>
#include <thread>

#include <CLI/CLI.hpp>

#include "bearer_token.h"
#include "service.h"
#include "util/error.h"

int main(int argc, char** argv) {
    using facetlight::server::Service;
    using facetlight::server::ServiceConfig;
    ServiceConfig config;
    std::string host = "127.0.0.1";
    int port = 8080;
    CLI::App app{"facetlight-server: the facetlight render service (JSON over HTTP)"};
    app.set_version_flag("--version", "facetlight-server 0.1.0");
    app.add_option("--host", host, "Address to bind (0.0.0.0 exposes the service to the network)")
        ->capture_default_str();
    app.add_option("--port", port, "TCP port")->capture_default_str()->check(CLI::Range(0, 65535));
    app.add_option("--data", config.dataDir, "Folder for the job store and results")->capture_default_str();
    app.add_option("--meshes", config.meshesDir, "Folder of shipped meshes (.obj, .stl, .asc, .gem)")
        ->capture_default_str();
    app.add_option("--web", config.webDir, "Folder of the web page served at /")->capture_default_str();
    app.add_option(
           "--three-js", config.threeDir,
           "Folder of three.js (Debian's libjs-three) for the page's 3-D view, served at /vendor/three/ "
           "(empty: none)")
        ->capture_default_str();
    auto& l = config.limits;
    app.add_option("--max-photons", l.maxPhotons, "Most photons per job (trace, and photon map)")
        ->capture_default_str()
        ->check(CLI::Range(uint64_t(1), uint64_t(10'000'000'000ULL)));
    app.add_option("--max-image", l.maxImageSide, "Largest render width or height in pixels")
        ->capture_default_str()
        ->check(CLI::Range(16, 4096));
    app.add_option("--max-upload", l.maxUploadBytes, "Largest mesh upload in bytes")
        ->capture_default_str()
        ->check(CLI::Range(size_t(1), size_t(1) << 30));
    app.add_option("--max-mesh-store", l.maxMeshStoreBytes,
                   "Most bytes the uploaded meshes may take together; an upload beyond gets 507")
        ->capture_default_str();
    app.add_option("--max-job-seconds", l.maxJobSeconds,
                   "Seconds a job may be estimated to take here: longer gets 422, and a job running twice "
                   "as long is stopped (0: no limit)")
        ->capture_default_str()
        ->check(CLI::Range(0.0, 1e7));
    app.add_option("--max-queue", l.maxQueued, "Most jobs waiting in the queue")
        ->capture_default_str()
        ->check(CLI::Range(size_t(1), size_t(100000)));
    app.add_option("--max-body", l.maxBodyBytes, "Largest job request body in bytes")
        ->capture_default_str()
        ->check(CLI::Range(size_t(256), size_t(64) << 20));
    app.add_option("--min-free", l.minFreeBytes,
                   "Bytes kept free on the data disk: below this, new jobs and uploads get 507")
        ->capture_default_str();
    app.add_option("--http-threads", config.http.threads, "Threads answering HTTP requests at first")
        ->capture_default_str()
        ->check(CLI::Range(1, 256));
    app.add_option("--max-http-threads", config.http.maxThreads,
                   "Threads added while every one is busy (slow clients), at most this many")
        ->capture_default_str()
        ->check(CLI::Range(1, 1024));
    app.add_option("--max-connections-per-peer", config.http.maxPerPeer,
                   "Connections one address may hold open at once; more get 429")
        ->capture_default_str()
        ->check(CLI::Range(1, 4096));
    double requestTimeout = std::chrono::duration<double>(config.http.requestTimeout).count();
    app.add_option("--request-timeout", requestTimeout,
                   "Seconds a request (line, headers and body) may take to arrive")
        ->capture_default_str()
        ->check(CLI::Range(0.1, 3600.0));
    app.add_option("--min-body-rate", config.http.minBodyRate,
                   "Bytes a second a request body must keep coming at after its first 2 s; slower gets 408 "
                   "(0: no minimum)")
        ->capture_default_str()
        ->check(CLI::Range(size_t(0), size_t(1) << 30));
    app.add_option("--cores", config.cores, "Cap on a job's threads (0: all the machine's cores)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1024));
    app.add_option(
        "--allowed-host", config.allowedHosts,
        "A name the server is reached by besides localhost, 127.0.0.1 and [::1] (and --host), without "
        "a port; repeatable. Requests for other Host names get 421, changes from other Origins 403");
    std::string tokenFile;
    bool noAuth = false;
    auto* tokenOption = app.add_option(
        "--token-file", tokenFile,
        "File whose first line is the token every /api request must carry (Authorization: Bearer TOKEN); "
        "needed with a --host other than loopback");
    app.add_flag("--no-auth", noAuth,
                 "Serve a --host other than loopback without a token: anyone who reaches it may use it")
        ->excludes(tokenOption);
    app.add_flag("!--no-access-log", config.accessLog, "Do not log each request on stderr");
    std::string launcher;
    facetlight::server::LaunchSettings launch;
    app.add_option("--launcher", launcher,
                   "Run jobs as child processes through this command, e.g. 'mpirun -np 4 --hostfile hosts'");
    app.add_option("--launcher-min-photons", launch.minPhotons,
                   "With --launcher: jobs with fewer photons (trace + photon map) run in-process")
        ->capture_default_str();
    app.add_option("--launcher-workdir", launch.workDir,
                   "With --launcher: folder for the children's job files, shared by every node");
    CLI11_PARSE(app, argc, argv);
    config.http.requestTimeout = std::chrono::milliseconds(int64_t(requestTimeout * 1000));
    if (!tokenFile.empty()) {
        try {
            config.token = facetlight::server::readTokenFile(tokenFile);
        } catch (const facetlight::Error& e) {
            std::cerr << "facetlight-server: --token-file: " << e.what() << "\n";
            return 2;
        }
    } else if (!noAuth && !facetlight::server::isLoopbackAddress(host)) {
        std::cerr
            << "facetlight-server: --host " << host
            << " is not a loopback address: give --token-file FILE, whose first line clients then send as "
               "Authorization: Bearer TOKEN, or --no-auth to let anyone who reaches it in\n";
        return 2;
    }
    // The address bound, unless it is every address, is a name the server is reached by.
    if (host != "0.0.0.0" && host != "::")
        config.allowedHosts.push_back(host.find(':') == std::string::npos ? host : "[" + host + "]");
    if (!launcher.empty()) {
        try {
            launch.launcher = facetlight::server::splitWords(launcher);
        } catch (const facetlight::Error& e) {
            std::cerr << "facetlight-server: --launcher: " << e.what() << "\n";
            return 2;
        }
        config.launch = launch;
    }

    // Signals go to one thread that waits for them; every other thread (HTTP pool, worker) inherits the mask.
    sigset_t signals;
    sigemptyset(&signals);
    sigaddset(&signals, SIGINT);
    sigaddset(&signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &signals, nullptr);
    std::signal(SIGPIPE, SIG_IGN);

    try {
        Service service(config);
        // Port 0: the system chooses a free port, and the line below tells which.
        const int requested = port;
        const bool bound =
            requested == 0 ? (port = service.bindToAnyPort(host)) > 0 : service.bind(host, port);
        if (!bound) {
            std::cerr << "facetlight-server: cannot listen on " << host << ":" << requested << "\n";
            return 1;
        }
        std::atomic<bool> signaled{false};
        std::thread waiter([&] {
            int sig = 0;
            sigwait(&signals, &sig);
            signaled = true;
            std::cerr << "facetlight-server: " << (sig == SIGINT ? "SIGINT" : "SIGTERM") << ", stopping\n";
            service.stop();
        });
        std::cerr << "facetlight-server: listening on http://" << host << ":" << port << "/ (data "
                  << config.dataDir << ")\n";
        service.listen();
        // listen() ends through stop(), or on a socket error: then wake the waiter ourselves.
        if (!signaled) kill(getpid(), SIGTERM);
        waiter.join();
        std::cerr << "facetlight-server: stopped\n";
    } catch (const facetlight::Error& e) {
        std::cerr << "facetlight-server: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "facetlight-server: internal error: " << e.what() << "\n";
        return 2;
    }
    return 0;
}
