#pragma once
// Progress for a parent process (the service's launcher, docs/distributed.md): JSON lines on stderr such as
// {"phase":"tracing","done":123,"total":1000}, written by a sampling thread whenever the numbers change, and
// once more at the end. Only rank 0 of a distributed run writes them.
#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>

#include <nlohmann/json.hpp>

#include "util/run_control.h"

namespace facetlight::cli {

class ProgressJson {
  public:
    // Does nothing unless `enabled`. `control` counts this process's share of each phase; jobUnits(phase)
    // gives the units of the phase over every rank, to which the share's progress is scaled, as if every
    // rank kept pace. Called from the reporting thread.
    ProgressJson(bool enabled, const RunControl& control, std::function<uint64_t(RunPhase)> jobUnits)
        : control_(control), jobUnits_(std::move(jobUnits)) {
        if (enabled) thread_ = std::thread([this] { run(); });
    }
    ~ProgressJson() {
        if (!thread_.joinable()) return;
        {
            std::lock_guard lock(mutex_);
            stop_ = true;
        }
        wake_.notify_all();
        thread_.join();
    }
    ProgressJson(const ProgressJson&) = delete;
    ProgressJson& operator=(const ProgressJson&) = delete;

  private:
    void run() {
        std::string last;
        std::unique_lock lock(mutex_);
        for (;;) {
            const bool stopping =
                wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stop_; });
            const RunPhase phase = control_.phase();
            const uint64_t done = control_.done(), total = control_.total(), units = jobUnits_(phase);
            const uint64_t jobDone =
                total ? uint64_t(static_cast<unsigned __int128>(done) * units / total) : 0;
            const nlohmann::json j = {
                {"phase", runPhaseName(phase)}, {"done", std::min(jobDone, units)}, {"total", units}};
            std::string line = j.dump() + "\n";
            if (line != last) {
                // One write per line, so lines from this thread never interleave with each other.
                std::cerr << line << std::flush;
                last = std::move(line);
            }
            if (stopping) return;
        }
    }

    const RunControl& control_;
    std::function<uint64_t(RunPhase)> jobUnits_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace facetlight::cli
