#include "launcher.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <optional>
#include <random>
#include <sstream>
#include <thread>

#include <nlohmann/json.hpp>

#include "util/error.h"

extern char** environ;

namespace facetlight::server {
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

constexpr size_t kTailBytes = 4096;

std::string defaultExecutable() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("launcher: cannot find this program's directory to locate facetlight");
    return (self.parent_path() / "facetlight").string();
}

std::optional<std::string> readFile(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A fresh, private job folder under `dir`, removed again when the job is over.
class JobFolder {
  public:
    explicit JobFolder(const fs::path& dir) {
        std::string pattern =
            ((dir.empty() ? fs::temp_directory_path() : dir) / "facetlight-job-XXXXXX").string();
        if (!mkdtemp(pattern.data()))
            throw Error("launcher: cannot create a job folder in " +
                        fs::path(pattern).parent_path().string() + ": " + std::strerror(errno));
        path_ = pattern;
    }
    ~JobFolder() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

void appendTail(std::string& tail, std::string_view line) {
    tail.append(line).push_back('\n');
    if (tail.size() > kTailBytes) tail.erase(0, tail.size() - kTailBytes);
}

// Waits for the child for up to `wait`; true when it has been reaped into `status`.
bool reap(pid_t pid, int& status, std::chrono::milliseconds wait) {
    const auto until = Clock::now() + wait;
    for (;;) {
        const pid_t r = waitpid(pid, &status, WNOHANG);
        if (r == pid || (r < 0 && errno != EINTR)) return true;
        if (Clock::now() >= until) return false;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
}

}  // namespace

std::vector<std::string> splitWords(std::string_view text) {
    std::vector<std::string> words;
    std::string word;
    bool inWord = false;
    char quote = 0;
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quote) {
            if (c == quote) {
                quote = 0;
            } else if (c == '\\' && quote == '"' && i + 1 < text.size()) {
                word.push_back(text[++i]);
            } else {
                word.push_back(c);
            }
        } else if (c == '\'' || c == '"') {
            quote = c;
            inWord = true;
        } else if (c == '\\' && i + 1 < text.size()) {
            word.push_back(text[++i]);
            inWord = true;
        } else if (c == ' ' || c == '\t' || c == '\n') {
            if (inWord) words.push_back(std::move(word));
            word.clear();
            inWord = false;
        } else {
            word.push_back(c);
            inWord = true;
        }
    }
    if (quote) throw Error(std::string("launcher: unclosed ") + quote + " in '" + std::string(text) + "'");
    if (inWord) words.push_back(std::move(word));
    return words;
}

bool useLauncher(const LaunchSettings& launch, const StudySettings& settings) {
    const uint64_t photons = settings.trace.photons + (settings.render ? settings.render->mapPhotons : 0);
    return photons >= launch.minPhotons;
}

bool applyProgressLine(std::string_view line, RunControl& control) {
    if (line.empty() || line.front() != '{') return false;
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (!j.is_object() || !j.contains("phase") || !j["phase"].is_string()) return false;
    const std::optional<RunPhase> phase = runPhaseNamed(j["phase"].get<std::string>());
    if (!phase) return false;
    const auto count = [&](const char* key) {
        const auto it = j.find(key);
        return it != j.end() && it->is_number_unsigned() ? it->get<uint64_t>() : uint64_t(0);
    };
    control.show(*phase, count("done"), count("total"));
    return true;
}

ChildExit runChild(const std::vector<std::string>& argv, const std::function<bool(std::string_view)>& onLine,
                   const RunControl& control, std::chrono::milliseconds cancelGrace) {
    if (argv.empty()) throw Error("launcher: nothing to run");
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw Error(std::string("launcher: pipe: ") + std::strerror(errno));

    posix_spawn_file_actions_t actions;
    posix_spawnattr_t attr;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
    posix_spawnattr_init(&attr);
    // A group of its own (pgid = its pid), so one kill reaches the launcher and everything it starts; and
    // default signal handling, whatever the service set for itself.
    posix_spawnattr_setpgroup(&attr, 0);
    sigset_t none, all;
    sigemptyset(&none);
    sigfillset(&all);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &all);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close(fds[1]);
    if (spawned != 0) {
        close(fds[0]);
        throw Error("launcher: cannot start '" + argv[0] + "': " + std::strerror(spawned));
    }

    ChildExit result;
    std::string pending;
    int status = 0;
    bool reaped = false;
    auto handleLines = [&](bool flush) {
        size_t start = 0;
        for (size_t nl; (nl = pending.find('\n', start)) != std::string::npos; start = nl + 1) {
            const std::string_view line(pending.data() + start, nl - start);
            if (!onLine(line)) appendTail(result.tail, line);
        }
        pending.erase(0, start);
        if (flush && !pending.empty()) {
            if (!onLine(pending)) appendTail(result.tail, pending);
            pending.clear();
        }
    };
    try {
        std::array<char, 4096> buffer;
        for (bool open = true; open;) {
            if (control.cancelled() && !result.cancelled) {
                result.cancelled = true;
                kill(-pid, SIGTERM);
                if (!reap(pid, status, cancelGrace)) {
                    kill(-pid, SIGKILL);
                    reap(pid, status, std::chrono::hours(1));
                }
                reaped = true;
                break;
            }
            pollfd p{fds[0], POLLIN, 0};
            if (poll(&p, 1, 100) <= 0) {
                // Something the child left behind may hold the pipe open: the child's end is the job's end.
                if (waitpid(pid, &status, WNOHANG) == pid) {
                    reaped = true;
                    open = false;
                }
                continue;
            }
            const ssize_t n = read(fds[0], buffer.data(), buffer.size());
            if (n < 0 && (errno == EINTR || errno == EAGAIN)) continue;
            if (n <= 0) open = false;
            if (n > 0) pending.append(buffer.data(), size_t(n));
            handleLines(!open);
        }
        handleLines(true);
    } catch (...) {
        kill(-pid, SIGKILL);
        close(fds[0]);
        waitpid(pid, &status, 0);
        throw;
    }
    close(fds[0]);
    if (!reaped) {
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
    }
    if (WIFEXITED(status)) result.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
    return result;
}

StudyResult runStudyInChild(const LaunchSettings& launch, const ChildMesh& mesh,
                            const StudySettings& settings, RunControl& control) {
    const JobFolder folder(launch.workDir);
    nlohmann::json job = {{"mesh", mesh.source}, {"trace", toJson(settings.trace)}};
    if (!mesh.name.empty()) job["name"] = mesh.name;
    if (settings.render) job["render"] = toJson(*settings.render);
    const fs::path jobFile = folder.path() / "job.json";
    {
        std::ofstream out(jobFile);
        out << job.dump(2);
        if (!(out << std::flush)) throw Error("launcher: cannot write " + jobFile.string());
    }

    std::vector<std::string> argv = launch.launcher;
    argv.push_back(launch.executable.empty() ? defaultExecutable() : launch.executable);
    for (const char* a : {"study", "--progress-json", "--job"}) argv.emplace_back(a);
    argv.push_back(jobFile.string());
    argv.emplace_back("--out");
    argv.push_back(folder.path().string());

    const ChildExit exit = runChild(
        argv, [&](std::string_view line) { return applyProgressLine(line, control); }, control,
        launch.cancelGrace);
    if (exit.cancelled) throw Canceled();
    const std::string command = argv.front();
    if (exit.signal != 0)
        throw Error("launcher: '" + command + "' was killed by signal " + std::to_string(exit.signal) + ": " +
                    exit.tail);
    if (exit.exitCode != 0)
        throw Error("launcher: '" + command + "' failed with exit code " + std::to_string(exit.exitCode) +
                    ": " + exit.tail);

    StudyResult result;
    const auto stats = readFile(folder.path() / "stats.json");
    if (!stats)
        throw Error("launcher: the job left no results in " + folder.path().string() +
                    " (is it a directory every node shares?): " + exit.tail);
    result.stats = nlohmann::json::parse(*stats);
    result.statsCsv = readFile(folder.path() / "stats.csv").value_or("");
    result.renderPng = readFile(folder.path() / "render.png").value_or("");
    result.heatmapPng = readFile(folder.path() / "heatmap.png").value_or("");
    result.heatmapLayout = readFile(folder.path() / "heatmap.json").value_or("");
    result.angularPng = readFile(folder.path() / "angular.png").value_or("");
    return result;
}

}  // namespace facetlight::server
