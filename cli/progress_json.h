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

namespace facetlight::cli {

struct ProgressSample {
    std::string phase;
    uint64_t done = 0, total = 0;
    bool operator==(const ProgressSample&) const = default;
};

// A rank's progress through its share `localTotal` of a job of `jobTotal` units, as the job's.
inline ProgressSample jobProgress(std::string phase, uint64_t localDone, uint64_t localTotal,
                                  uint64_t jobTotal) {
    const uint64_t done =
        localTotal ? uint64_t(double(localDone) / double(localTotal) * double(jobTotal)) : 0;
    return {std::move(phase), std::min(done, jobTotal), jobTotal};
}

class ProgressJson {
  public:
    // Does nothing unless `enabled`; `sample` is called from the reporting thread.
    ProgressJson(bool enabled, std::function<ProgressSample()> sample) : sample_(std::move(sample)) {
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
        ProgressSample last{"", ~uint64_t(0), 0};
        std::unique_lock lock(mutex_);
        for (;;) {
            const bool stopping =
                wake_.wait_for(lock, std::chrono::milliseconds(200), [this] { return stop_; });
            const ProgressSample now = sample_();
            if (!(now == last)) {
                // One write per line, so lines from this thread never interleave with each other.
                const nlohmann::json j = {{"phase", now.phase}, {"done", now.done}, {"total", now.total}};
                std::cerr << (j.dump() + "\n") << std::flush;
                last = now;
            }
            if (stopping) return;
        }
    }

    std::function<ProgressSample()> sample_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stop_ = false;
    std::thread thread_;
};

}  // namespace facetlight::cli
