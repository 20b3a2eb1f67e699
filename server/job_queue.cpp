#include "job_queue.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <iostream>
#include <new>

#include "study/result_files.h"
#include "util/error.h"

namespace facetlight::server {
namespace {

// How often the worker retries writing states the store refused.
constexpr auto kRetrySaving = std::chrono::seconds(1);
// The worker and the tracing threads it starts (Linux threads inherit it) yield to the HTTP threads: status
// polls are answered at once while a job keeps every core busy.
constexpr int kWorkerNice = 10;

// What a client reads when the server's own storage failed under a job.
constexpr const char* kStorageFailed =
    "the server could not store the results (its storage is full or failing)";
constexpr const char* kStartNotRecorded =
    "the server could not record that the job started (its storage is full or failing); it was not run";

}  // namespace

JobQueue::JobQueue(JobStore& store, ResultStore& results, StudyRunner& runner, size_t maxQueued,
                   uint64_t minFreeBytes, int cores, JobBudget budget)
    : store_(store),
      results_(results),
      runner_(runner),
      maxQueued_(maxQueued),
      minFreeBytes_(minFreeBytes),
      cores_(std::max(1, cores)),
      budget_(budget) {}

JobQueue::~JobQueue() {
    stop();
}

void JobQueue::start(bool runJobs) {
    std::lock_guard lock(mutex_);
    for (JobRecord& job : store_.unfinishedJobs()) {
        if (job.cancelRequested) {  // acknowledged, then a crash came before the job stopped
            job.state = JobState::Canceled;
            job.finishedAt = nowIso8601();
            record(job);
            continue;
        }
        const bool wasRunning = job.state == JobState::Running;
        job.state = JobState::Queued;
        job.startedAt.clear();
        job.threadsUsed = 0;
        queued_.push_back(job.id);
        if (wasRunning && runJobs) {
            record(job);
        } else {
            const std::string id = job.id;  // the move below may come first
            held_[id] = std::make_shared<const JobRecord>(std::move(job));
        }
    }
    if (!queued_.empty())
        std::cerr << "facetlight-server: " << queued_.size() << " job(s) queued from the store\n";
    stopping_ = false;
    if (runJobs) worker_ = std::thread([this] { workerLoop(); });
}

void JobQueue::stop() {
    {
        std::lock_guard lock(mutex_);
        if (!worker_.joinable()) return;
        stopping_ = true;
        if (running_) running_->cancel();
    }
    wake_.notify_all();
    worker_.join();
}

bool JobQueue::record(const JobRecord& job) {
    auto& held = held_[job.id];
    held = std::make_shared<const JobRecord>(job);
    try {
        store_.saveState(job);
    } catch (const StorageError& e) {
        std::cerr << "facetlight-server: job " << job.id << ": recording '" << jobStateName(job.state)
                  << "' failed, kept in memory until the store takes writes: " << e.what() << "\n";
        unsaved_.insert(job.id);
        return false;
    }
    unsaved_.erase(job.id);
    if (isFinished(job.state)) held_.erase(job.id);
    return true;
}

void JobQueue::saveUnsaved() {
    for (auto it = unsaved_.begin(); it != unsaved_.end();) {
        try {
            if (deleted_.count(*it)) {
                store_.deleteJob(*it);
                deleted_.erase(*it);
            } else if (const auto held = held_.find(*it); held != held_.end()) {
                store_.saveState(*held->second);
                if (isFinished(held->second->state)) held_.erase(held);
            }
            std::cerr << "facetlight-server: job " << *it << ": recorded now\n";
            it = unsaved_.erase(it);
        } catch (const StorageError&) {
            ++it;  // still refused: again later
        }
    }
}

bool JobQueue::submit(JobRecord& job) {
    {
        std::lock_guard lock(mutex_);
        if (queued_.size() >= maxQueued_) return false;
        store_.insertJob(job);
        held_[job.id] = std::make_shared<const JobRecord>(job);
        queued_.push_back(job.id);
    }
    wake_.notify_one();
    return true;
}

JobQueue::CancelOutcome JobQueue::cancel(const std::string& id) {
    std::lock_guard lock(mutex_);
    if (const auto it = std::find(queued_.begin(), queued_.end(), id); it != queued_.end()) {
        queued_.erase(it);
        JobRecord job = *held_.at(id);
        job.state = JobState::Canceled;
        job.finishedAt = nowIso8601();
        record(job);
        return CancelOutcome::Canceled;
    }
    if (running_ && runningId_ == id) {
        // Recorded before the answer, so that a crash before the job stops cannot run it again (issue 31).
        // A store that refuses writes is the degraded mode of record(): the job stops, and its end is kept
        // in memory until the store takes writes.
        try {
            store_.requestCancel(id);
        } catch (const StorageError& e) {
            std::cerr << "facetlight-server: job " << id << ": recording the cancel failed: " << e.what()
                      << "\n";
        }
        running_->cancel();
        return CancelOutcome::Requested;
    }
    return CancelOutcome::NotActive;
}

bool JobQueue::remove(const std::string& id) {
    const auto found = job(id);
    if (!found || !isFinished(found->state)) return false;
    std::lock_guard lock(mutex_);
    results_.clear(id);
    held_.erase(id);
    try {
        if (!store_.deleteJob(id)) return false;
        unsaved_.erase(id);
    } catch (const StorageError& e) {
        std::cerr << "facetlight-server: job " << id
                  << ": deleting its record failed, it stays hidden until the store takes writes: "
                  << e.what() << "\n";
        deleted_.insert(id);
        unsaved_.insert(id);
    }
    return true;
}

std::shared_ptr<const JobRecord> JobQueue::job(const std::string& id) const {
    {
        std::lock_guard lock(mutex_);
        if (deleted_.count(id)) return nullptr;
        if (const auto it = held_.find(id); it != held_.end()) return it->second;
    }
    auto stored = store_.job(id);
    return stored ? std::make_shared<const JobRecord>(std::move(*stored)) : nullptr;
}

std::vector<JobRecord> JobQueue::jobs(int limit, int offset) const {
    std::vector<JobRecord> stored = store_.jobs(limit, offset);
    std::lock_guard lock(mutex_);
    std::erase_if(stored, [&](const JobRecord& j) { return deleted_.count(j.id) != 0; });
    for (JobRecord& j : stored)
        if (const auto it = held_.find(j.id); it != held_.end()) j = *it->second;
    return stored;
}

int64_t JobQueue::jobCount() const {
    const int64_t stored = store_.jobCount();
    std::lock_guard lock(mutex_);
    return stored - int64_t(deleted_.size());
}

size_t JobQueue::unsavedCount() const {
    std::lock_guard lock(mutex_);
    return unsaved_.size();
}

std::optional<size_t> JobQueue::queuePosition(const std::string& id) const {
    std::lock_guard lock(mutex_);
    const auto it = std::find(queued_.begin(), queued_.end(), id);
    if (it == queued_.end()) return std::nullopt;
    return size_t(it - queued_.begin()) + 1;
}

std::shared_ptr<const RunControl> JobQueue::live(const std::string& id) const {
    std::lock_guard lock(mutex_);
    if (!running_ || runningId_ != id) return nullptr;
    return running_;
}

bool JobQueue::usesMesh(const std::string& mesh) const {
    std::lock_guard lock(mutex_);
    for (const auto& [id, job] : held_) {
        if (isFinished(job->state)) continue;
        const std::string named = job->spec ? job->spec->mesh : job->request.value("mesh", std::string());
        if (named == mesh) return true;
    }
    return false;
}

size_t JobQueue::queuedCount() const {
    std::lock_guard lock(mutex_);
    return queued_.size();
}

void JobQueue::workerLoop() {
    if (::setpriority(PRIO_PROCESS, ::gettid(), kWorkerNice) != 0)
        std::cerr << "facetlight-server: cannot lower the worker's priority; status polls may wait on jobs\n";
    for (;;) {
        std::shared_ptr<RunControl> control;
        JobRecord job;
        std::string id;
        {
            std::unique_lock lock(mutex_);
            wake_.wait_for(lock, kRetrySaving, [this] { return stopping_ || !queued_.empty(); });
            if (!unsaved_.empty()) saveUnsaved();
            if (stopping_) return;
            if (queued_.empty()) continue;
            job = *held_.at(queued_.front());
            queued_.pop_front();
            control = std::make_shared<RunControl>();
            running_ = control;
            runningId_ = job.id;
        }
        try {
            runJob(std::move(job), *control);
        } catch (const std::exception& e) {  // the store itself failed: log it, keep serving
            std::cerr << "facetlight-server: job " << runningId_ << ": " << e.what() << "\n";
        }
        std::lock_guard lock(mutex_);
        running_.reset();
        runningId_.clear();
    }
}

void JobQueue::runJob(JobRecord job, RunControl& control) {
    const std::string& id = job.id;
    // The watchdog lets go of `control` however the job ends.
    struct Release {
        JobWatchdog& watchdog;
        ~Release() { watchdog.release(); }
    } release{watchdog_};
    std::chrono::steady_clock::time_point started;
    const auto finish = [&](JobState state, const std::string& error = {}) {
        job.state = state;
        job.finishedAt = nowIso8601();
        job.error = error;
        std::lock_guard lock(mutex_);
        record(job);
    };
    try {
        // A job whose results cannot fit fails now with the reason, rather than after its work.
        if (const std::string shortage = results_.spaceShortage(minFreeBytes_); !shortage.empty())
            return finish(JobState::Failed, shortage + ": the job was not run");
        if (!job.spec) {
            results_.clear(id);
            return finish(JobState::Failed, job.specError);
        }
        // Parsed when the job was accepted (or read back from the store); a copy runs with its threads.
        JobRequest spec = *job.spec;
        const int threads = threadsFor(spec);
        spec.settings.trace.threads = threads;
        job.state = JobState::Running;
        job.startedAt = nowIso8601();
        job.threadsUsed = threads;
        bool recorded;
        {
            std::lock_guard lock(mutex_);
            recorded = record(job);
        }
        if (!recorded) return finish(JobState::Failed, kStartNotRecorded);
        // A study re-run after a crash starts from nothing; a sweep resumes from the points it kept.
        const bool sweep = spec.settings.sweep.has_value();
        if (!sweep) results_.clear(id);
        started = std::chrono::steady_clock::now();
        if (budget_.runSeconds() > 0) watchdog_.watch(control, budget_.runSeconds());
        const StudyResult result =
            runner_.run(spec, control, sweep ? sweepCheckpoint(results_, id) : SweepCheckpoint{});
        try {
            for (const ResultFile& f : kResultFiles)
                if (std::string bytes = result.bytes(f); !bytes.empty())
                    results_.write(id, std::string(f.name), bytes);
        } catch (const std::exception& e) {
            // A full or failing disk: the detail (with paths) goes to the log, the job gets a reason a
            // client may see, and no partial results stay behind.
            std::cerr << "facetlight-server: job " << id << ": storing results failed: " << e.what() << "\n";
            results_.clear(id);
            return finish(JobState::Failed, kStorageFailed);
        }
        finish(JobState::Succeeded);
    } catch (const Canceled&) {
        // Stopped over its budget: failed for good, also when the service was stopping at the same moment.
        if (watchdog_.release()) {
            const std::chrono::duration<double> ran = std::chrono::steady_clock::now() - started;
            results_.clear(id);  // a sweep's kept points
            return finish(JobState::Failed, budget_.overrun(ran.count()));
        }
        bool shuttingDown;
        {
            std::lock_guard lock(mutex_);
            shuttingDown = stopping_;
        }
        if (shuttingDown) {
            job.state = JobState::Queued;  // a sweep keeps its finished points for the restart
            job.startedAt.clear();
            job.threadsUsed = 0;
            std::lock_guard lock(mutex_);
            record(job);
        } else {
            results_.clear(id);
            finish(JobState::Canceled);
        }
    } catch (const Error& e) {
        results_.clear(id);  // a sweep's kept points
        finish(JobState::Failed, e.what());
    } catch (const std::bad_alloc&) {
        finish(JobState::Failed, "out of memory: ask for fewer photons or a smaller image");
    } catch (const std::exception& e) {
        std::cerr << "facetlight-server: job " << id << " failed: " << e.what() << "\n";
        finish(JobState::Failed, std::string("internal error: ") + e.what());
    }
}

}  // namespace facetlight::server
