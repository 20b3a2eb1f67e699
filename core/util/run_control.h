#pragma once
// One run's progress and cancel, passed to every phase of a trace or study and read by whoever watches it
// (the CLI's progress line and JSON lines, the service's job status, the launcher following a child process).
// All atomics: workers advance `done` once per block, watchers read without a lock, and a cancel request is
// checked before each block.
#include <atomic>
#include <cstdint>
#include <exception>
#include <optional>
#include <string_view>

namespace facetlight {

enum class RunPhase : uint8_t { Queued, Tracing, Viewing, PhotonMap, Rendering, Done };
std::string_view runPhaseName(RunPhase phase);
// The phase runPhaseName gives `name`; none for any other name.
std::optional<RunPhase> runPhaseNamed(std::string_view name);

// What a sweep or a study throws when its RunControl's cancel stops it (the phases below them return a
// `cancelled` flag instead); caught where the job is run.
class Canceled : public std::exception {
  public:
    const char* what() const noexcept override { return "canceled"; }
};

class RunControl {
  public:
    // A phase of `total` units (photons, pixels) of this process's share, none done yet.
    void startPhase(RunPhase phase, uint64_t total) { show(phase, 0, total); }
    // Progress as another process reports it (the launcher's child).
    void show(RunPhase phase, uint64_t done, uint64_t total) {
        done_.store(done, std::memory_order_relaxed);
        total_.store(total, std::memory_order_relaxed);
        phase_.store(phase, std::memory_order_release);
    }
    void advance(uint64_t units) { done_.fetch_add(units, std::memory_order_relaxed); }

    // Runs made of whole items (a sweep's points) in stages (the search's rounds): stage `stage` (from 1) of
    // `stages` begins with `items` items, none finished.
    void startStage(int stage, int stages, uint64_t items) {
        itemsDone_.store(0, std::memory_order_relaxed);
        itemsTotal_.store(items, std::memory_order_relaxed);
        stages_.store(stages, std::memory_order_relaxed);
        stage_.store(stage, std::memory_order_release);
    }
    void finishItem() { itemsDone_.fetch_add(1, std::memory_order_relaxed); }
    uint64_t itemsDone() const { return itemsDone_.load(std::memory_order_relaxed); }
    uint64_t itemsTotal() const { return itemsTotal_.load(std::memory_order_relaxed); }
    int stage() const { return stage_.load(std::memory_order_acquire); }  // 0: the run has no stages
    int stages() const { return stages_.load(std::memory_order_relaxed); }

    // Asks the run to stop: workers claim no further block; the phase reports that it was cancelled.
    void cancel() { cancel_.store(true, std::memory_order_relaxed); }
    bool cancelled() const { return cancel_.load(std::memory_order_relaxed); }

    RunPhase phase() const { return phase_.load(std::memory_order_acquire); }
    uint64_t done() const { return done_.load(std::memory_order_relaxed); }
    uint64_t total() const { return total_.load(std::memory_order_relaxed); }
    // done / total, 0 without a total.
    double fraction() const {
        const uint64_t t = total();
        return t ? double(done()) / double(t) : 0.0;
    }

  private:
    std::atomic<RunPhase> phase_{RunPhase::Queued};
    std::atomic<uint64_t> done_{0}, total_{0};
    std::atomic<uint64_t> itemsDone_{0}, itemsTotal_{0};
    std::atomic<int> stage_{0}, stages_{0};
    // Read before every block by every worker: kept off the cache line that `done` is written on.
    alignas(64) std::atomic<bool> cancel_{false};
};

}  // namespace facetlight
