#pragma once
// Stops a running job that outlives its budget (job_budget.h): a thread that waits until the job's time is up
// and then cancels its RunControl, the path a client's cancel takes. Whoever runs the job asks afterwards
// whether the stop was the watchdog's.
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "util/run_control.h"

namespace facetlight::server {

class JobWatchdog {
  public:
    JobWatchdog();
    ~JobWatchdog();
    JobWatchdog(const JobWatchdog&) = delete;
    JobWatchdog& operator=(const JobWatchdog&) = delete;

    // Cancels `control` once `seconds` have passed, unless release() comes first or the run was cancelled
    // already (a client's cancel, a shutdown: not the watchdog's). `control` must outlive the watch.
    void watch(RunControl& control, double seconds);
    // Stops watching; true when the time ran out and the watchdog cancelled the run (once: a second call
    // says false).
    bool release();

  private:
    void loop();

    std::mutex mutex_;
    std::condition_variable wake_;
    RunControl* control_ = nullptr;
    std::chrono::steady_clock::time_point deadline_;
    bool fired_ = false, stopping_ = false;
    std::thread thread_;
};

}  // namespace facetlight::server
