#pragma once
// The jobs table of the service's database: each job's request, state and times. Their result files are
// the ResultStore's (result_store.h), uploaded meshes MeshStore's (mesh_store.h).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "database.h"
#include "study/job_request.h"

namespace facetlight::server {

enum class JobState { Queued, Running, Succeeded, Failed, Canceled };
std::string_view jobStateName(JobState state);
JobState parseJobState(std::string_view name);  // throws Error
inline bool isFinished(JobState s) {
    return s != JobState::Queued && s != JobState::Running;
}

struct JobRecord {
    std::string id;
    int64_t seq = 0;  // submission order
    JobState state = JobState::Queued;
    // The job, parsed once: on submission, or from the store's text when its record is read back. Null when
    // the stored text no longer reads as a job (`specError` says why).
    std::shared_ptr<const JobRequest> spec;
    nlohmann::json request;  // the spec's canonical JSON (toJson, every default written out), as stored
    std::string specError;
    std::string createdAt, startedAt, finishedAt;  // ISO 8601 UTC; empty until it happens
    std::string error;                             // why it failed
    int threadsUsed = 0;           // threads the worker gave it (the request capped at the cores)
    bool cancelRequested = false;  // a cancel of it running was acknowledged: a restart cancels it
};

class JobStore {
  public:
    explicit JobStore(Database& db) : db_(db) {}

    void insertJob(JobRecord& job);  // sets job.seq
    std::optional<JobRecord> job(const std::string& id) const;
    std::vector<JobRecord> jobs(int limit, int offset) const;  // newest first
    int64_t jobCount() const;
    // Queued jobs and those a crash left running, oldest first.
    std::vector<JobRecord> unfinishedJobs() const;

    // Writes the job's state, times, error and threads. Throws StorageError when the store cannot be written.
    void saveState(const JobRecord& job);
    // Records that the running job was asked to stop, before the client is told. Throws StorageError.
    void requestCancel(const std::string& id);
    // Removes a job; false when there was no such job.
    bool deleteJob(const std::string& id);

  private:
    Database& db_;
};

}  // namespace facetlight::server
