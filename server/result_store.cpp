#include "result_store.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

#include "database.h"
#include "util/error.h"

namespace facetlight::server {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void fail(const std::string& what, const fs::path& path) {
    const int error = errno;
    throw StorageError("cannot " + what + " " + path.string() + ": " + std::strerror(error),
                       error == ENOSPC || error == EDQUOT);
}

// Flushes a folder's entries (a file created or renamed in it) to the disk.
void syncDirectory(const fs::path& dir) {
    const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) fail("open", dir);
    const bool synced = ::fsync(fd) == 0;
    ::close(fd);
    if (!synced) fail("sync", dir);
}

}  // namespace

void writeFileAtomically(const fs::path& path, std::string_view bytes) {
    const fs::path tmp = path.string() + ".tmp";
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail("write", tmp);
    if (simulatedFullDisk().files) {
        ::close(fd);
        ::unlink(tmp.c_str());
        errno = ENOSPC;
        fail("write", tmp);
    }
    size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        written += size_t(n);
    }
    const bool ok = written == bytes.size() && ::fsync(fd) == 0;
    const int savedErrno = errno;
    if (::close(fd) != 0 || !ok) {
        errno = ok ? errno : savedErrno;
        std::error_code ec;
        fs::remove(tmp, ec);
        fail("write", tmp);
    }
    std::error_code renamed;
    fs::rename(tmp, path, renamed);
    if (renamed) {
        fs::remove(tmp, renamed);
        errno = renamed.value();
        fail("rename", tmp);
    }
    syncDirectory(path.parent_path());
}

ResultStore::ResultStore(fs::path dir) : dir_(std::move(dir)) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) throw Error("cannot create result directory " + dir_.string() + ": " + ec.message());
    removeTemporaryFiles(dir_);
}

void removeTemporaryFiles(const fs::path& dir) {
    std::error_code ec;
    std::vector<fs::path> leftovers;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec))
        if (it->path().extension() == ".tmp") leftovers.push_back(it->path());
    for (const fs::path& p : leftovers) fs::remove(p, ec);  // a read-only disk keeps them: nothing to do
}

uint64_t ResultStore::freeBytes() const {
    if (simulatedFullDisk().files) return 0;
    std::error_code ec;
    const fs::space_info space = fs::space(dir_, ec);
    return ec ? 0 : space.available;
}

std::string ResultStore::spaceShortage(uint64_t minFree) const {
    const uint64_t free = freeBytes();
    if (free >= minFree) return {};
    return "the server's storage is nearly full (" + std::to_string(free >> 20) + " MiB free, " +
           std::to_string(minFree >> 20) + " MiB kept free)";
}

std::string ResultStore::writeRefusal() const {
    std::lock_guard lock(probeMutex_);
    const auto now = std::chrono::steady_clock::now();
    if (probedAt_.time_since_epoch().count() != 0 && now - probedAt_ < std::chrono::seconds(1))
        return probeRefusal_;
    probedAt_ = now;
    // A `.tmp` name: a crash between the write and the removal leaves what every start removes.
    const fs::path probe = dir_ / ".write-probe.tmp";
    int error = 0;
    if (simulatedFullDisk().files) {
        error = ENOSPC;
    } else if (const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644); fd < 0) {
        error = errno;
    } else {
        if (::write(fd, "x", 1) != 1) error = errno;
        ::close(fd);
        ::unlink(probe.c_str());
    }
    probeRefusal_ =
        error ? std::string("the server's storage takes no more writes (") + std::strerror(error) + ")"
              : std::string();
    return probeRefusal_;
}

fs::path ResultStore::jobDir(const std::string& jobId) const {
    if (!isId(jobId)) throw Error("invalid job id");
    return dir_ / jobId;
}

void ResultStore::write(const std::string& jobId, const std::string& name, std::string_view bytes) {
    const fs::path dir = jobDir(jobId);
    std::error_code ec;
    if (fs::create_directories(dir, ec)) syncDirectory(dir_);
    if (ec) {
        errno = ec.value();
        fail("create", dir);
    }
    writeFileAtomically(dir / name, bytes);
}

std::optional<std::string> ResultStore::read(const std::string& jobId, const std::string& name) const {
    std::ifstream in(jobDir(jobId) / name, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream ss;
    ss << in.rdbuf();
    return std::move(ss).str();
}

std::vector<std::string> ResultStore::names(const std::string& jobId, const std::string& prefix) const {
    std::vector<std::string> found;
    std::error_code ec;
    for (auto it = fs::directory_iterator(jobDir(jobId), ec); !ec && it != fs::directory_iterator();
         it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.compare(0, prefix.size(), prefix) == 0 && it->path().extension() != ".tmp")
            found.push_back(name);
    }
    std::sort(found.begin(), found.end());
    return found;
}

void ResultStore::clear(const std::string& jobId) {
    std::error_code ec;
    fs::remove_all(jobDir(jobId), ec);
}

std::string sweepPointFile(size_t round, size_t point) {
    char name[64];
    std::snprintf(name, sizeof name, "%s%zu-%06zu.json", kSweepPointPrefix, round, point);
    return name;
}

SweepCheckpoint sweepCheckpoint(ResultStore& files, const std::string& jobId) {
    return {[&files, jobId](size_t round, size_t point) -> std::optional<nlohmann::json> {
                const std::optional<std::string> bytes = files.read(jobId, sweepPointFile(round, point));
                if (!bytes) return std::nullopt;
                // A file the crash cut short is never there (written atomically); one that does not parse is
                // traced again.
                nlohmann::json j = nlohmann::json::parse(*bytes, nullptr, false);
                return j.is_discarded() ? std::nullopt : std::optional(std::move(j));
            },
            [&files, jobId](size_t round, size_t point, const nlohmann::json& j) {
                // A point that cannot be kept (a full disk) is traced again after a restart; the sweep goes
                // on.
                try {
                    files.write(jobId, sweepPointFile(round, point), j.dump());
                } catch (const std::exception& e) {
                    std::fprintf(stderr, "facetlight-server: job %s: %s\n", jobId.c_str(), e.what());
                }
            }};
}

}  // namespace facetlight::server
