#include "job_store.h"

#include <sqlite3.h>

#include "job_spec.h"
#include "util/error.h"

namespace facetlight::server {
namespace {

constexpr const char* kJobColumns =
    "SELECT seq, id, state, request, created_at, started_at, finished_at, error, threads_used, "
    "cancel_requested "
    "FROM jobs ";

JobRecord readJob(const Statement& s) {
    JobRecord j;
    j.seq = s.integer(0);
    j.id = s.text(1);
    j.state = parseJobState(s.text(2));
    j.request = nlohmann::json::parse(s.text(3));
    try {
        j.spec = std::make_shared<const JobRequest>(storedJobSpec(j.request));
    } catch (const std::exception& e) {  // the job still lists; it fails if run
        j.specError = e.what();
    }
    j.createdAt = s.text(4);
    j.startedAt = s.text(5);
    j.finishedAt = s.text(6);
    j.error = s.text(7);
    j.cancelRequested = s.integer(9) != 0;
    j.threadsUsed = int(s.integer(8));
    return j;
}

}  // namespace

std::string_view jobStateName(JobState state) {
    switch (state) {
        case JobState::Queued:
            return "queued";
        case JobState::Running:
            return "running";
        case JobState::Succeeded:
            return "succeeded";
        case JobState::Failed:
            return "failed";
        case JobState::Canceled:
            return "canceled";
    }
    return "queued";
}

JobState parseJobState(std::string_view name) {
    for (JobState s :
         {JobState::Queued, JobState::Running, JobState::Succeeded, JobState::Failed, JobState::Canceled}) {
        if (jobStateName(s) == name) return s;
    }
    throw Error("unknown job state '" + std::string(name) + "'");
}

void JobStore::insertJob(JobRecord& job) {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(), "INSERT INTO jobs (id, state, request, created_at) VALUES (?, ?, ?, ?)");
    s.bind(1, job.id).bind(2, jobStateName(job.state)).bind(3, job.request.dump()).bind(4, job.createdAt);
    s.step();
    job.seq = sqlite3_last_insert_rowid(db_.handle());
}

std::optional<JobRecord> JobStore::job(const std::string& id) const {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(), (std::string(kJobColumns) + "WHERE id = ?").c_str());
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return readJob(s);
}

std::vector<JobRecord> JobStore::jobs(int limit, int offset) const {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(), (std::string(kJobColumns) + "ORDER BY seq DESC LIMIT ? OFFSET ?").c_str());
    s.bind(1, int64_t(limit)).bind(2, int64_t(offset));
    std::vector<JobRecord> out;
    while (s.step()) out.push_back(readJob(s));
    return out;
}

int64_t JobStore::jobCount() const {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(), "SELECT COUNT(*) FROM jobs");
    s.step();
    return s.integer(0);
}

std::vector<JobRecord> JobStore::unfinishedJobs() const {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(),
                (std::string(kJobColumns) + "WHERE state IN ('queued', 'running') ORDER BY seq").c_str());
    std::vector<JobRecord> out;
    while (s.step()) out.push_back(readJob(s));
    return out;
}

void JobStore::saveState(const JobRecord& job) {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(),
                "UPDATE jobs SET state = ?, started_at = ?, finished_at = ?, error = ?, threads_used = ? "
                "WHERE id = ?");
    s.bind(1, jobStateName(job.state))
        .bind(2, job.startedAt)
        .bind(3, job.finishedAt)
        .bind(4, job.error)
        .bind(5, int64_t(job.threadsUsed))
        .bind(6, job.id);
    s.step();
}

void JobStore::requestCancel(const std::string& id) {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(), "UPDATE jobs SET cancel_requested = 1 WHERE id = ?");
    s.bind(1, id);
    s.step();
}

bool JobStore::deleteJob(const std::string& id) {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(), "DELETE FROM jobs WHERE id = ?");
    s.bind(1, id);
    s.step();
    return sqlite3_changes(db_.handle()) != 0;
}

}  // namespace facetlight::server
