#pragma once
// The service's SQLite database (WAL) under <data>/facetlight.db, shared by the job and mesh stores: one
// connection, used by the HTTP threads and the worker in turn under one lock, its schema brought up to date
// on opening. Also the identifiers and timestamps the stored records carry.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <string>
#include <string_view>

#include "util/error.h"

struct sqlite3;
struct sqlite3_stmt;

namespace facetlight::server {

// A fresh random 128-bit identifier as 32 lowercase hex digits (unguessable: from std::random_device).
std::string newId();
bool isId(std::string_view s);
std::string nowIso8601();

// The store could not write: a full disk (`full`), a read-only or failing one. Its message has the paths and
// goes to the log; clients get a reason without them (issue 18).
class StorageError : public Error {
  public:
    StorageError(const std::string& message, bool full) : Error(message), full_(full) {}
    bool full() const { return full_; }

  private:
    bool full_;
};

// Test hook (only tests set it): while `files` is set, every file the store writes fails as on a full disk
// and the disk reports no free space; while `database` is set, every database write does. Lets tests drive
// each write failure without filling a disk.
struct SimulatedFullDisk {
    std::atomic<bool> files{false}, database{false};
};
SimulatedFullDisk& simulatedFullDisk();

class Database {
  public:
    // Opens (creating when needed) <dataDir>/facetlight.db and brings its schema up to date. On a read-only
    // disk it opens the database read-only instead (readOnlyReason() says why); throws Error when it cannot.
    explicit Database(const std::filesystem::path& dataDir);
    ~Database();
    Database(const Database&) = delete;
    Database& operator=(const Database&) = delete;

    // Hold this while using handle().
    std::mutex& mutex() const { return mutex_; }
    sqlite3* handle() const { return db_; }
    void exec(const char* sql) const;
    // Empty when the store can be written.
    const std::string& readOnlyReason() const { return readOnlyReason_; }

  private:
    void openWritable(const std::string& dbPath, bool exclusive);
    void openReadOnly(const std::string& dbPath);
    sqlite3* db_ = nullptr;
    std::string readOnlyReason_;
    mutable std::mutex mutex_;
};

// A prepared statement that finalizes itself; errors become Error with SQLite's message.
class Statement {
  public:
    Statement(sqlite3* db, const char* sql);
    ~Statement();
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;

    Statement& bind(int i, std::string_view text);
    Statement& bind(int i, int64_t v);
    bool step();  // true while there is a row
    std::string text(int col) const;
    int64_t integer(int col) const;

  private:
    [[noreturn]] void fail() const;
    sqlite3* db_;
    sqlite3_stmt* stmt_ = nullptr;
};

}  // namespace facetlight::server
