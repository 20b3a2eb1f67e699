#pragma once
// The durable side of the service: jobs and uploaded meshes in SQLite (WAL), result files under
// <data>/jobs/<id>/, each written to a temporary name and renamed, so a crash never leaves half a file.
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

struct sqlite3;

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
    nlohmann::json request;  // the validated job, normalised (every default written out)
    std::string createdAt, startedAt, finishedAt;  // ISO 8601 UTC; empty until it happens
    std::string error;                             // why it failed
    int threadsUsed = 0;  // threads the worker gave it (the request capped at the cores)
};

struct MeshRecord {
    std::string id;
    std::string name;    // the file name it was uploaded as, cleaned
    std::string format;  // obj, stl or asc
    std::string createdAt;
    nlohmann::json summary;  // stoneSummaryJson of the built stone
};

// A fresh random 128-bit identifier as 32 lowercase hex digits (unguessable: from std::random_device).
std::string newId();
bool isId(std::string_view s);
std::string nowIso8601();

class JobStore {
  public:
    // Opens (creating when needed) <dataDir>/facetlight.db and brings its schema up to date.
    explicit JobStore(std::filesystem::path dataDir);
    ~JobStore();
    JobStore(const JobStore&) = delete;
    JobStore& operator=(const JobStore&) = delete;

    void insertJob(JobRecord& job);  // sets job.seq
    std::optional<JobRecord> job(const std::string& id) const;
    std::vector<JobRecord> jobs(int limit, int offset) const;  // newest first
    int64_t jobCount() const;
    // Jobs a crash left running go back to `queued`; returns every queued job's id, oldest first.
    std::vector<std::string> recoverQueued();

    void markRunning(const std::string& id, int threadsUsed);
    void markFinished(const std::string& id, JobState state, const std::string& error = {});
    void markQueued(const std::string& id);  // a running job handed back at shutdown
    // Removes a job and its result files; false when there was no such job.
    bool deleteJob(const std::string& id);

    // Result files. writeResult() writes <name>.tmp then renames it over <name>.
    void writeResult(const std::string& id, const std::string& name, std::string_view bytes);
    std::optional<std::string> readResult(const std::string& id, const std::string& name) const;
    void clearResults(const std::string& id);

    void insertMesh(const MeshRecord& mesh, std::string_view bytes);
    std::optional<MeshRecord> mesh(const std::string& id) const;
    std::vector<MeshRecord> meshes() const;
    std::filesystem::path meshFile(const MeshRecord& mesh) const;

    const std::filesystem::path& dataDir() const { return dataDir_; }

  private:
    std::filesystem::path jobDir(const std::string& id) const;
    void exec(const char* sql) const;

    std::filesystem::path dataDir_;
    sqlite3* db_ = nullptr;
    mutable std::mutex mutex_;  // one connection, used by the HTTP threads and the worker in turn
};

// Writes bytes to path via path.tmp and a rename (atomic on POSIX file systems).
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace facetlight::server
