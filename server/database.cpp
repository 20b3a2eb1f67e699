#include "database.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <random>

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
    // A cancel of a running job is recorded before it is acknowledged (issue 31): a crash before the job
    // stops does not run it again.
    "ALTER TABLE jobs ADD COLUMN cancel_requested INTEGER NOT NULL DEFAULT 0;",
};

// Whether a file can be created in `dir`: EROFS (or a permission error) means a read-only store.
std::string writeProbe(const fs::path& dir) {
    const fs::path probe = dir / ".write-probe";
    const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0600);
    if (fd < 0) return errno == ENOSPC || errno == EDQUOT ? std::string() : std::strerror(errno);
    ::close(fd);
    ::unlink(probe.c_str());
    return {};
}

}  // namespace

SimulatedFullDisk& simulatedFullDisk() {
    static SimulatedFullDisk full;
    return full;
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

Statement::Statement(sqlite3* db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK) fail();
}

Statement::~Statement() {
    sqlite3_finalize(stmt_);
}

Statement& Statement::bind(int i, std::string_view text) {
    if (sqlite3_bind_text(stmt_, i, text.data(), int(text.size()), SQLITE_TRANSIENT) != SQLITE_OK) fail();
    return *this;
}

Statement& Statement::bind(int i, int64_t v) {
    if (sqlite3_bind_int64(stmt_, i, v) != SQLITE_OK) fail();
    return *this;
}

bool Statement::step() {
    if (simulatedFullDisk().database && !sqlite3_stmt_readonly(stmt_))
        throw StorageError("job store: database or disk is full (simulated)", true);
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc != SQLITE_DONE) fail();
    return false;
}

std::string Statement::text(int col) const {
    const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, col));
    return p ? std::string(p, size_t(sqlite3_column_bytes(stmt_, col))) : std::string();
}

int64_t Statement::integer(int col) const {
    return sqlite3_column_int64(stmt_, col);
}

namespace {

// SQLite's codes for a disk that refuses writes become StorageError.
[[noreturn]] void throwStoreError(int rc, const std::string& message) {
    if (rc == SQLITE_FULL || rc == SQLITE_IOERR || rc == SQLITE_READONLY || rc == SQLITE_CANTOPEN)
        throw StorageError(message, rc == SQLITE_FULL);
    throw Error(message);
}

}  // namespace

void Statement::fail() const {
    throwStoreError(sqlite3_errcode(db_), std::string("job store: ") + sqlite3_errmsg(db_));
}

Database::Database(const fs::path& dataDir) {
    std::error_code ec;
    fs::create_directories(dataDir, ec);
    if (ec) throw Error("cannot create data directory " + dataDir.string() + ": " + ec.message());
    const std::string dbPath = (dataDir / "facetlight.db").string();
    readOnlyReason_ = writeProbe(dataDir);
    if (!readOnlyReason_.empty()) {
        openReadOnly(dbPath);
        return;
    }
    try {
        openWritable(dbPath, false);
    } catch (const StorageError&) {
        // A full disk: SQLite cannot create the shared-memory index (-shm) beside the database. Held
        // exclusively it keeps that index in memory (sqlite.org/wal.html#noshm), so the server still starts
        // and deletes can free space; only when that fails too does it open read-only.
        sqlite3_close(db_);
        db_ = nullptr;
        try {
            openWritable(dbPath, true);
        } catch (const StorageError&) {
            sqlite3_close(db_);
            db_ = nullptr;
            readOnlyReason_ = "the disk is full: the database cannot be opened for writing";
            openReadOnly(dbPath);
        }
    }
}

void Database::openWritable(const std::string& dbPath, bool exclusive) {
    if (sqlite3_open_v2(dbPath.c_str(), &db_,
                        SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
        const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        db_ = nullptr;
        throw Error("cannot open job store " + dbPath + ": " + msg);
    }
    sqlite3_busy_timeout(db_, 5000);
    if (exclusive) exec("PRAGMA locking_mode=EXCLUSIVE");
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

// A read-only disk changes under no one: SQLite may read the database as immutable, without the -shm file
// it could not create there.
void Database::openReadOnly(const std::string& dbPath) {
    const std::string uri = "file:" + dbPath + "?immutable=1";
    if (sqlite3_open_v2(uri.c_str(), &db_, SQLITE_OPEN_READONLY | SQLITE_OPEN_URI | SQLITE_OPEN_FULLMUTEX,
                        nullptr) != SQLITE_OK) {
        const std::string msg = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        throw Error("cannot open job store " + dbPath + " read-only: " + msg);
    }
    Statement version(db_, "PRAGMA user_version");
    version.step();
    if (version.integer(0) != int64_t(std::size(kMigrations)))
        throw Error("job store " + dbPath + " is read-only (" + readOnlyReason_ +
                    ") and has schema version " + std::to_string(version.integer(0)) + ", not " +
                    std::to_string(std::size(kMigrations)));
}

Database::~Database() {
    sqlite3_close(db_);
}

void Database::exec(const char* sql) const {
    char* err = nullptr;
    if (const int rc = sqlite3_exec(db_, sql, nullptr, nullptr, &err); rc != SQLITE_OK) {
        const std::string msg = err ? err : sqlite3_errmsg(db_);
        sqlite3_free(err);
        throwStoreError(rc, "job store: " + msg);
    }
}

}  // namespace facetlight::server
