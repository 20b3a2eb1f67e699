#pragma once
// The service's store of result files on disk: a job's files under <dir>/<job id>/ (their names are core's
// kResultFiles, study/result_files.h). Each is written to a temporary name, flushed to the disk and
// renamed over its name, and the folder flushed after the rename: after a crash or a power cut a result is
// there whole or not at all.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "sweep/sweep_job.h"

namespace facetlight::server {

class ResultStore {
  public:
    // `dir` holds one folder per job; created when missing. Temporary files left by a crash or a full disk
    // are removed.
    explicit ResultStore(std::filesystem::path dir);

    void write(const std::string& jobId, const std::string& name, std::string_view bytes);
    std::optional<std::string> read(const std::string& jobId, const std::string& name) const;
    // The names of the job's files that begin with `prefix`, sorted.
    std::vector<std::string> names(const std::string& jobId, const std::string& prefix) const;
    void clear(const std::string& jobId);  // every result of the job, and its folder
    // Bytes free for results on the disk that holds them (the most a non-root writer may use).
    uint64_t freeBytes() const;
    // Why new work must wait for space ("the server's storage is nearly full (3 MiB free, 256 MiB kept
    // free)"); empty while at least `minFree` bytes are free.
    std::string spaceShortage(uint64_t minFree) const;
    // Why nothing can be written where results go ("no space left on device"): a byte written to a probe file
    // was refused. Empty when it was taken. Probed at most once a second; the answer is kept in between.
    std::string writeRefusal() const;

  private:
    std::filesystem::path jobDir(const std::string& jobId) const;
    std::filesystem::path dir_;
    mutable std::mutex probeMutex_;
    mutable std::chrono::steady_clock::time_point probedAt_{};
    mutable std::string probeRefusal_;
};

// Removes the `.tmp` files a crash or a full disk left anywhere under `dir`.
void removeTemporaryFiles(const std::filesystem::path& dir);
// A sweep's finished points, one file each in the job's folder ("point-<round>-<index>.json", the point as
// sweep.json lists it), written as they finish and read back when an interrupted sweep resumes.
std::string sweepPointFile(size_t round, size_t point);
constexpr const char* kSweepPointPrefix = "point-";
SweepCheckpoint sweepCheckpoint(ResultStore& files, const std::string& jobId);

// Writes bytes to path.tmp, fsyncs it, renames it over path and fsyncs path's folder (POSIX: the rename is
// atomic, and durable once the folder is synced). Throws Error.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes);

}  // namespace facetlight::server
