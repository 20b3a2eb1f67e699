#include "job_queue.h"

#include <algorithm>
#include <iostream>
#include <new>

#include "job_spec.h"
#include "study/result_files.h"
#include "util/error.h"

namespace facetlight::server {

JobQueue::JobQueue(JobStore& store, ResultFiles& results, StudyRunner& runner, size_t maxQueued, int cores)
    : store_(store),
      results_(results),
      runner_(runner),
      maxQueued_(maxQueued),
      cores_(std::max(1, cores)) {}

JobQueue::~JobQueue() {
    stop();
}

void JobQueue::start() {
    std::lock_guard lock(mutex_);
    for (auto& id : store_.recoverQueued()) queued_.push_back(std::move(id));
    if (!queued_.empty())
        std::cerr << "facetlight-server: " << queued_.size() << " job(s) queued from the store\n";
    stopping_ = false;
    worker_ = std::thread([this] { workerLoop(); });
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

bool JobQueue::submit(JobRecord& job) {
    {
        std::lock_guard lock(mutex_);
        if (queued_.size() >= maxQueued_) return false;
        store_.insertJob(job);
        queued_.push_back(job.id);
    }
    wake_.notify_one();
    return true;
}

JobQueue::CancelOutcome JobQueue::cancel(const std::string& id) {
    std::lock_guard lock(mutex_);
    if (const auto it = std::find(queued_.begin(), queued_.end(), id); it != queued_.end()) {
        queued_.erase(it);
        store_.markFinished(id, JobState::Canceled);
        return CancelOutcome::Canceled;
    }
    if (running_ && runningId_ == id) {
        running_->cancel();
        return CancelOutcome::Requested;
    }
    return CancelOutcome::NotActive;
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

size_t JobQueue::queuedCount() const {
    std::lock_guard lock(mutex_);
    return queued_.size();
}

void JobQueue::workerLoop() {
    for (;;) {
        std::shared_ptr<RunControl> control;
        std::string id;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [this] { return stopping_ || !queued_.empty(); });
            if (stopping_) return;
            id = queued_.front();
            queued_.pop_front();
            control = std::make_shared<RunControl>();
            running_ = control;
            runningId_ = id;
        }
        try {
            runJob(id, *control);
        } catch (const std::exception& e) {  // the store itself failed: log it, keep serving
            std::cerr << "facetlight-server: job " << id << ": " << e.what() << "\n";
        }
        std::lock_guard lock(mutex_);
        running_.reset();
        runningId_.clear();
    }
}

// What a client reads when the server's own storage failed under a job.
constexpr const char* kStorageFailed = "the server could not store the results (its storage is full or failing)";

void JobQueue::runJob(const std::string& id, RunControl& control) {
    try {
        const auto job = store_.job(id);
        if (!job) return;  // deleted while queued
        StudySpec spec = parseJobSpec(job->request, cores_);
        const int threads = std::min(spec.settings.trace.threads, cores_);
        spec.settings.trace.threads = threads;
        store_.markRunning(id, threads);
        // A study re-run after a crash starts from nothing; a sweep resumes from the points it kept.
        const bool sweep = spec.settings.sweep.has_value();
        if (!sweep) results_.clear(id);
        const StudyResult result =
            runner_.run(spec, control, sweep ? sweepCheckpoint(results_, id) : SweepCheckpoint{});
        try {
            for (const ResultFile& f : kResultFiles)
                if (std::string bytes = f.bytes(result); !bytes.empty())
                    results_.write(id, std::string(f.name), bytes);
        } catch (const std::exception& e) {
            // A full or failing disk: the detail (with paths) goes to the log, the job gets a reason a
            // client may see, and no partial results stay behind.
            std::cerr << "facetlight-server: job " << id << ": storing results failed: " << e.what() << "\n";
            results_.clear(id);
            store_.markFinished(id, JobState::Failed, kStorageFailed);
            return;
        }
        store_.markFinished(id, JobState::Succeeded);
    } catch (const Canceled&) {
        bool shuttingDown;
        {
            std::lock_guard lock(mutex_);
            shuttingDown = stopping_;
        }
        if (shuttingDown) {
            store_.markQueued(id);  // a sweep keeps its finished points for the restart
        } else {
            results_.clear(id);
            store_.markFinished(id, JobState::Canceled);
        }
    } catch (const Error& e) {
        results_.clear(id);  // a sweep's kept points
        store_.markFinished(id, JobState::Failed, e.what());
    } catch (const std::bad_alloc&) {
        store_.markFinished(id, JobState::Failed, "out of memory: ask for fewer photons or a smaller image");
    } catch (const std::exception& e) {
        std::cerr << "facetlight-server: job " << id << " failed: " << e.what() << "\n";
        store_.markFinished(id, JobState::Failed, std::string("internal error: ") + e.what());
    }
}

}  // namespace facetlight::server
