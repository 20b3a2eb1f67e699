#include "child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <thread>

#include "util/error.h"

extern char** environ;

namespace facetlight::server {
namespace {

using Clock = std::chrono::steady_clock;
constexpr size_t kTailBytes = 4096;

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

// After a cancel, what the launcher started (the ranks) may outlive it for a moment, longer on a loaded
// machine where the job's processes run at a low priority: wait for the group to be gone, killing it after
// `wait`. Bounded: a member nobody reaps stays a zombie.
void awaitGroupEnd(pid_t group, std::chrono::milliseconds wait) {
    for (const bool killed : {false, true}) {
        const auto until = Clock::now() + wait;
        while (kill(-group, 0) == 0 && Clock::now() < until)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        if (killed || kill(-group, SIGKILL) != 0) return;
    }
}

}  // namespace

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
                awaitGroupEnd(pid, cancelGrace);
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

}  // namespace facetlight::server
