#include "job_store.h"

#include <sqlite3.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <random>
#include <sstream>

#include "util/error.h"

namespace facetlight::server {
namespace {

namespace fs = std::filesystem;

// Schema versions, applied in order; PRAGMA user_version records how many have run.
const char* const kMigrations[] = {
    R"(CREATE TABLE jobs (
           seq INTEGER PRIMARY KEY AUTOINCREMENT,
           id TEXT NOT NULL UNIQUE,
           state TEXT NOT NULL,
           request TEXT NOT NULL,
           created_at TEXT NOT NULL,
           started_at TEXT NOT NULL DEFAULT '',
           finished_at TEXT NOT NULL DEFAULT '',
           error TEXT NOT NULL DEFAULT '',
           threads_used INTEGER NOT NULL DEFAULT 0);
       CREATE INDEX jobs_state ON jobs(state);
       CREATE TABLE meshes (
           id TEXT PRIMARY KEY,
           name TEXT NOT NULL,
           format TEXT NOT NULL,
           created_at TEXT NOT NULL,
           summary TEXT NOT NULL);)",
};

// A prepared statement that finalizes itself; errors become Error with SQLite's message.
class Statement {
  public:
    Statement(sqlite3* db, const char* sql) : db_(db) {
        if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) fail();
    }
    ~Statement() { sqlite3_finalize(stmt_); }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;

    Statement& bind(int i, std::string_view text) {
        if (sqlite3_bind_text(stmt_, i, text.data(), int(text.size()), SQLITE_TRANSIENT) != SQLITE_OK) fail();
        return *this;
    }
    Statement& bind(int i, int64_t v) {
        if (sqlite3_bind_int64(stmt_, i, v) != SQLITE_OK) fail();
        return *this;
    }
    bool step() {  // true while there is a row
        const int rc = sqlite3_step(stmt_);
        if (rc == SQLITE_ROW) return true;
        if (rc != SQLITE_DONE) fail();
        return false;
    }
    std::string text(int col) const {
        const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, col));
        return p ? std::string(p, size_t(sqlite3_column_bytes(stmt_, col))) : std::string();
    }
    int64_t integer(int col) const { return sqlite3_column_int64(stmt_, col); }

  private:
    [[noreturn]] void fail() const { throw Error(std::string("job store: ") + sqlite3_errmsg(db_)); }
    sqlite3* db_;
    sqlite3_stmt* stmt_ = nullptr;
};

constexpr const char* kJobColumns =
    "SELECT seq, id, state, request, created_at, started_at, finished_at, error, threads_used FROM jobs ";

JobRecord readJob(const Statement& s) {
    JobRecord j;
    j.seq = s.integer(0);
    j.id = s.text(1);
    j.state = parseJobState(s.text(2));
    j.request = nlohmann::json::parse(s.text(3));
    j.createdAt = s.text(4);
    j.startedAt = s.text(5);
    j.finishedAt = s.text(6);
    j.error = s.text(7);
    j.threadsUsed = int(s.integer(8));
    return j;
}

MeshRecord readMesh(const Statement& s) {
    return {s.text(0), s.text(1), s.text(2), s.text(3), nlohmann::json::parse(s.text(4))};
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

std::string newId() {
    static std::mutex mutex;
    static std::random_device device;
    std::lock_guard lock(mutex);
    char buf[33];
    for (int i = 0; i < 4; ++i) std::snprintf(buf + 8 * i, 9, "%08x", unsigned(device()));
    return std::string(buf, 32);
}

bool isId(std::string_view s) {
    if (s.size() != 32) return false;
    for (char c : s) {
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    }
    return true;
}

std::string nowIso8601() {
    const auto now = std::chrono::system_clock::now();
    const std::time_t t = std::chrono::system_clock::to_time_t(now);
    const auto ms =
        std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count() % 1000;
    std::tm tm{};
    gmtime_r(&t, &tm);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1,
                  tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, int(ms));
    return buf;
}

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
    const fs::path tmp = path.string() + ".tmp";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out.write(bytes.data(), std::streamsize(bytes.size()));
        out.flush();
        if (!out) throw Error("cannot write " + tmp.string());
    }
    fs::rename(tmp, path);
}

JobStore::JobStore(fs::path dataDir) : dataDir_(std::move(dataDir)) {
    std::error_code ec;
    fs::create_directories(dataDir_ / "jobs", ec);
    fs::create_directories(dataDir_ / "meshes", ec);
    if (ec) throw Error("cannot create data directory " + dataDir_.string() + ": " + ec.message());
    const std::string dbPath = (dataDir_ / "facetlight.db").string();
    if (sqlite3_open_v2(dbPath.c_str(), &db_,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
        const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        throw Error("cannot open job store " + dbPath + ": " + msg);
    }
    sqlite3_busy_timeout(db_, 5000);
    exec("PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL; PRAGMA foreign_keys=ON;");
    Statement version(db_, "PRAGMA user_version");
    version.step();
    const int64_t applied = version.integer(0);
    const int64_t known = int64_t(std::size(kMigrations));
    if (applied > known) {
        throw Error("job store " + dbPath + " has schema version " + std::to_string(applied) +
                    ", newer than this server knows (" + std::to_string(known) + ")");
    }
    for (int64_t v = applied; v < known; ++v) {
        exec("BEGIN");
        try {
            exec(kMigrations[v]);
            exec(("PRAGMA user_version=" + std::to_string(v + 1)).c_str());
            exec("COMMIT");
        } catch (...) {
            exec("ROLLBACK");
            throw;
        }
    }
}

JobStore::~JobStore() {
    sqlite3_close(db_);
}

void JobStore::exec(const char* sql) const {
    char* err = nullptr;
    if (sqlite3_exec(db_, sql, nullptr, nullptr, &err) != SQLITE_OK) {
        const std::string msg = err ? err : sqlite3_errmsg(db_);
        sqlite3_free(err);
        throw Error("job store: " + msg);
    }
}

void JobStore::insertJob(JobRecord& job) {
    std::lock_guard lock(mutex_);
    Statement s(db_, "INSERT INTO jobs (id, state, request, created_at) VALUES (?, ?, ?, ?)");
    s.bind(1, job.id).bind(2, jobStateName(job.state)).bind(3, job.request.dump()).bind(4, job.createdAt);
    s.step();
    job.seq = sqlite3_last_insert_rowid(db_);
}

std::optional<JobRecord> JobStore::job(const std::string& id) const {
    std::lock_guard lock(mutex_);
    Statement s(db_, (std::string(kJobColumns) + "WHERE id = ?").c_str());
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return readJob(s);
}

std::vector<JobRecord> JobStore::jobs(int limit, int offset) const {
    std::lock_guard lock(mutex_);
    Statement s(db_, (std::string(kJobColumns) + "ORDER BY seq DESC LIMIT ? OFFSET ?").c_str());
    s.bind(1, int64_t(limit)).bind(2, int64_t(offset));
    std::vector<JobRecord> out;
    while (s.step()) out.push_back(readJob(s));
    return out;
}

int64_t JobStore::jobCount() const {
    std::lock_guard lock(mutex_);
    Statement s(db_, "SELECT COUNT(*) FROM jobs");
    s.step();
    return s.integer(0);
}

std::vector<std::string> JobStore::recoverQueued() {
    std::lock_guard lock(mutex_);
    Statement reset(db_,
                    "UPDATE jobs SET state = 'queued', started_at = '', threads_used = 0 "
                    "WHERE state = 'running'");
    reset.step();
    Statement s(db_, "SELECT id FROM jobs WHERE state = 'queued' ORDER BY seq");
    std::vector<std::string> ids;
    while (s.step()) ids.push_back(s.text(0));
    return ids;
}

void JobStore::markRunning(const std::string& id, int threadsUsed) {
    std::lock_guard lock(mutex_);
    Statement s(db_, "UPDATE jobs SET state = 'running', started_at = ?, threads_used = ? WHERE id = ?");
    s.bind(1, nowIso8601()).bind(2, int64_t(threadsUsed)).bind(3, id);
    s.step();
}

void JobStore::markFinished(const std::string& id, JobState state, const std::string& error) {
    std::lock_guard lock(mutex_);
    Statement s(db_, "UPDATE jobs SET state = ?, finished_at = ?, error = ? WHERE id = ?");
    s.bind(1, jobStateName(state)).bind(2, nowIso8601()).bind(3, error).bind(4, id);
    s.step();
}

void JobStore::markQueued(const std::string& id) {
    std::lock_guard lock(mutex_);
    Statement s(db_, "UPDATE jobs SET state = 'queued', started_at = '', threads_used = 0 WHERE id = ?");
    s.bind(1, id);
    s.step();
}

bool JobStore::deleteJob(const std::string& id) {
    {
        std::lock_guard lock(mutex_);
        Statement s(db_, "DELETE FROM jobs WHERE id = ?");
        s.bind(1, id);
        s.step();
        if (sqlite3_changes(db_) == 0) return false;
    }
    clearResults(id);
    return true;
}

fs::path JobStore::jobDir(const std::string& id) const {
    if (!isId(id)) throw Error("invalid job id");
    return dataDir_ / "jobs" / id;
}

void JobStore::writeResult(const std::string& id, const std::string& name, std::string_view bytes) {
    const fs::path dir = jobDir(id);
    fs::create_directories(dir);
    writeFileAtomically(dir / name, bytes);
}

std::optional<std::string> JobStore::readResult(const std::string& id, const std::string& name) const {
    std::ifstream in(jobDir(id) / name, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    return std::move(ss).str();
}

void JobStore::clearResults(const std::string& id) {
    std::error_code ec;
    fs::remove_all(jobDir(id), ec);
}

void JobStore::insertMesh(const MeshRecord& mesh, std::string_view bytes) {
    writeFileAtomically(meshFile(mesh), bytes);
    std::lock_guard lock(mutex_);
    Statement s(db_, "INSERT INTO meshes (id, name, format, created_at, summary) VALUES (?, ?, ?, ?, ?)");
    s.bind(1, mesh.id)
        .bind(2, mesh.name)
        .bind(3, mesh.format)
        .bind(4, mesh.createdAt)
        .bind(5, mesh.summary.dump());
    s.step();
}

std::optional<MeshRecord> JobStore::mesh(const std::string& id) const {
    std::lock_guard lock(mutex_);
    Statement s(db_, "SELECT id, name, format, created_at, summary FROM meshes WHERE id = ?");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return readMesh(s);
}

std::vector<MeshRecord> JobStore::meshes() const {
    std::lock_guard lock(mutex_);
    Statement s(db_, "SELECT id, name, format, created_at, summary FROM meshes ORDER BY created_at DESC");
    std::vector<MeshRecord> out;
    while (s.step()) out.push_back(readMesh(s));
    return out;
}

fs::path JobStore::meshFile(const MeshRecord& mesh) const {
    if (!isId(mesh.id)) throw Error("invalid mesh id");
    return dataDir_ / "meshes" / (mesh.id + "." + mesh.format);
}

}  // namespace facetlight::server
