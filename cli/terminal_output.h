#pragma once
// What the subcommands write: result files, and a one-line progress display on stderr while work runs
// (header-only: the CLI's build takes its sources from cli/*_command.cpp).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <thread>

#include "stone/stone.h"
#include "util/error.h"
#include "util/run_control.h"

namespace facetlight::cli {

inline void writeFile(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary);
    if (!out || !out.write(bytes.data(), std::streamsize(bytes.size())) || !out.flush())
        throw Error("cannot write " + path.string());
}

// A stone's trade proportions, one per line ("-" where one does not apply), as `info` and `cut` print them
// (scripts/make-meshes reads the second field, or the third after a two-word label).
inline void printProportions(const Proportions& p) {
    auto line = [](const char* label, const std::optional<double>& v, const char* unit) {
        if (v)
            std::printf("  %-18s %8.2f %s\n", label, *v, unit);
        else
            std::printf("  %-18s %8s\n", label, "-");
    };
    std::printf("  %-18s %8.3f\n", "length/width", p.length / p.width);
    line("table", p.tablePct, "%");
    line("crown height", p.crownHeightPct, "%");
    line("girdle", p.girdlePct, "%");
    line("pavilion depth", p.pavilionDepthPct, "%");
    line("total depth", p.totalDepthPct, "%");
    line("crown angle", p.crownAngleDeg, "deg");
    line("pavilion angle", p.pavilionAngleDeg, "deg");
}

// Redraws the run's phase and a bar of its progress on stderr every 100 ms while it lives, only when stderr
// is a terminal and `wanted`.
class ProgressLine {
  public:
    ProgressLine(bool wanted, const RunControl& control) {
        if (!wanted || !isatty(STDERR_FILENO)) return;
        thread_ = std::thread([this, &control] {
            while (!finished_.load()) {
                std::fprintf(stderr, "\r%-60s",
                             bar(runPhaseName(control.phase()), control.fraction()).c_str());
                std::fflush(stderr);
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
            std::fprintf(stderr, "\r%60s\r", "");
        });
    }
    ~ProgressLine() {
        finished_ = true;
        if (thread_.joinable()) thread_.join();
    }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    static std::string bar(std::string_view label, double share) {
        const int width = 40, filled = int(std::clamp(share, 0.0, 1.0) * width);
        return std::string(label) + " [" + std::string(filled, '#') + std::string(width - filled, ' ') +
               "] " + std::to_string(int(100 * share)) + "%";
    }

  private:
    std::atomic<bool> finished_{false};
    std::thread thread_;
};

}  // namespace facetlight::cli
