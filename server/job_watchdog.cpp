#include "job_watchdog.h"

#include <utility>

namespace facetlight::server {

JobWatchdog::JobWatchdog() : thread_([this] { loop(); }) {}

JobWatchdog::~JobWatchdog() {
    {
        std::lock_guard lock(mutex_);
        stopping_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void JobWatchdog::watch(RunControl& control, double seconds) {
    {
        std::lock_guard lock(mutex_);
        control_ = &control;
        fired_ = false;
        deadline_ = std::chrono::steady_clock::now() +
                    std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                        std::chrono::duration<double>(seconds));
    }
    wake_.notify_all();
}

bool JobWatchdog::release() {
    std::lock_guard lock(mutex_);
    control_ = nullptr;
    return std::exchange(fired_, false);
}

void JobWatchdog::loop() {
    std::unique_lock lock(mutex_);
    while (!stopping_) {
        if (!control_) {
            wake_.wait(lock);
        } else if (std::chrono::steady_clock::now() < deadline_) {
            wake_.wait_until(lock, deadline_);
        } else {
            if (!control_->cancelled()) {
                control_->cancel();
                fired_ = true;
            }
            control_ = nullptr;
        }
    }
}

}  // namespace facetlight::server
