#pragma once
// The bounded queue and its one worker thread: it queues jobs and moves their states in the store; its
// StudyRunner runs them, one at a time, off the HTTP threads, each with the threads it asked for capped at the
// machine's cores. Cancelling a running job cancels its RunControl; stopping the service hands the running job
// back to the queue, so it runs again after a restart.
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "job_store.h"
#include "result_files.h"
#include "study/study.h"
#include "study_runner.h"

namespace facetlight::server {

class JobQueue {
  public:
    JobQueue(JobStore& store, ResultFiles& results, StudyRunner& runner, size_t maxQueued, int cores);
    ~JobQueue();  // stop()

    // Re-queues what the store holds (jobs a crash left running first in their turn) and starts the worker.
    void start();
    // Stops the worker: the running job is cancelled and put back as queued.
    void stop();

    // Stores the job and queues it; false (and nothing stored) when the queue is full.
    bool submit(JobRecord& job);

    enum class CancelOutcome { Canceled, Requested, NotActive };
    // A queued job is canceled at once; a running one is asked to stop (its state follows shortly).
    CancelOutcome cancel(const std::string& id);

    std::optional<size_t> queuePosition(const std::string& id) const;  // 1 for the next to run
    // The running job's progress (read without a lock); none unless `id` is running.
    std::shared_ptr<const RunControl> live(const std::string& id) const;
    size_t queuedCount() const;
    int cores() const { return cores_; }

  private:
    void workerLoop();
    void runJob(const std::string& id, RunControl& control);

    JobStore& store_;
    ResultFiles& results_;
    StudyRunner& runner_;
    const size_t maxQueued_;
    const int cores_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<std::string> queued_;
    std::string runningId_;
    std::shared_ptr<RunControl> running_;
    bool stopping_ = false;
    std::thread worker_;
};

}  // namespace facetlight::server
