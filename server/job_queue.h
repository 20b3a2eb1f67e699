#pragma once
// The bounded queue and its one worker thread: it queues jobs and moves their states in the store; its
// StudyRunner runs them, one at a time, off the HTTP threads, each with the threads it asked for capped at
// the machine's cores. Cancelling a running job cancels its RunControl; stopping the service hands the
// running job back to the queue, so it runs again after a restart. A job that outlives its budget
// (job_budget.h) is cancelled the same way and fails with the reason.
//
// The queue keeps the record of every job it holds (queued or running) in memory, and status reads of those
// are answered from there: polls of a running job read no database and wait on no lock the job holds. A
// state the store could not record (a full or failing disk) stays in memory too, so clients still see every
// job reach its end, and the worker writes it once the store takes writes again (issue 18).
#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "job_budget.h"
#include "job_store.h"
#include "job_watchdog.h"
#include "result_store.h"
#include "study/study.h"
#include "study_runner.h"

namespace facetlight::server {

class JobQueue {
  public:
    // Jobs fail without running when the disk has less than `minFreeBytes` free: their results would not fit;
    // they are stopped when they run longer than budget.runSeconds().
    JobQueue(JobStore& store, ResultStore& results, StudyRunner& runner, size_t maxQueued,
             uint64_t minFreeBytes, int cores, JobBudget budget);
    ~JobQueue();  // stop()

    // Re-queues what the store holds (jobs a crash left running first in their turn) and, when `runJobs`
    // (false: a read-only store), starts the worker.
    void start(bool runJobs);
    // Stops the worker: the running job is cancelled and put back as queued.
    void stop();

    // Stores the job and queues it; false (and nothing stored) when the queue is full. Throws StorageError
    // when the store cannot record it.
    bool submit(JobRecord& job);

    enum class CancelOutcome { Canceled, Requested, NotActive };
    // A queued job is canceled at once; a running one is asked to stop (its state follows shortly).
    CancelOutcome cancel(const std::string& id);
    // Removes a finished job: its results first (that frees the disk), then its record. True when removed;
    // false when the job does not exist or has not finished.
    bool remove(const std::string& id);

    // A job as clients see it: from memory while the queue holds it, else from the store; none when unknown.
    std::shared_ptr<const JobRecord> job(const std::string& id) const;
    std::vector<JobRecord> jobs(int limit, int offset) const;  // newest first
    int64_t jobCount() const;
    // States and deletions the store has not recorded yet (its disk was full or failing).
    size_t unsavedCount() const;

    std::optional<size_t> queuePosition(const std::string& id) const;  // 1 for the next to run
    // The running job's progress (read without a lock); none unless `id` is running.
    std::shared_ptr<const RunControl> live(const std::string& id) const;
    size_t queuedCount() const;
    // Whether a queued or running job names `mesh` (an uploaded mesh may not be deleted under it).
    bool usesMesh(const std::string& mesh) const;
    int cores() const { return cores_; }
    const JobBudget& budget() const { return budget_; }
    // The threads a job of `spec` runs with: those it asks for, at most the machine's cores.
    int threadsFor(const JobRequest& spec) const { return std::min(spec.settings.trace.threads, cores_); }

  private:
    void workerLoop();
    void runJob(JobRecord job, RunControl& control);
    // With mutex_ held: makes `job` the queue's record of it and writes it to the store; false (and kept to
    // write later) when the store refused.
    bool record(const JobRecord& job);
    void saveUnsaved();  // with mutex_ held

    JobStore& store_;
    ResultStore& results_;
    StudyRunner& runner_;
    const size_t maxQueued_;
    const uint64_t minFreeBytes_;
    const int cores_;
    const JobBudget budget_;
    JobWatchdog watchdog_;

    mutable std::mutex mutex_;
    std::condition_variable wake_;
    std::unordered_map<std::string, std::shared_ptr<const JobRecord>> held_;  // queued, running, unsaved
    std::set<std::string> unsaved_;  // ids whose state or deletion the store lacks
    std::set<std::string> deleted_;  // deleted, but still in the store
    std::deque<std::string> queued_;
    std::string runningId_;
    std::shared_ptr<RunControl> running_;
    bool stopping_ = false;
    std::thread worker_;
};

}  // namespace facetlight::server
