#pragma once
// What the subcommands write: result files, and a one-line progress display on stderr while work runs
// (header-only: the CLI's build takes its sources from cli/*_command.cpp).
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <string_view>
#include <thread>

#include <nlohmann/json.hpp>

#include "stone/proportions.h"
#include "util/error.h"
#include "util/run_control.h"

namespace facetlight::cli {

inline void writeFile(const std::filesystem::path& path, std::string_view bytes) {
    std::ofstream out(path, std::ios::binary);
    if (!out || !out.write(bytes.data(), std::streamsize(bytes.size())) || !out.flush())
        throw Error("cannot write " + path.string());
}

// The ASET shares of a study's statistics ("aset" in docs/stats-schema.md), one class a line.
inline void printAsetShares(std::ostream& out, const nlohmann::json& aset) {
    out << "ASET shares of the face-up area (" << aset["rays"].get<uint64_t>() << " view rays):\n";
    for (const auto& [name, s] : aset["shares"].items()) {
        char line[96];
        std::snprintf(line, sizeof line, "  %-8s %6.2f%% +- %.2f\n", name.c_str(), 100 * s["share"].get<double>(),
                      100 * s["stderr"].get<double>());
        out << line;
    }
}

// A stone's trade proportions, one per line ("-" where one does not apply), as `info` and `cut` print them
// (scripts/make-meshes reads the figure after the label).
inline void printProportions(const Proportions& p) {
    std::printf("  %-18s %8.3f\n", "length/width", p.length / p.width);
    for (const ProportionField& field : kProportionFields) {
        const std::string label(field.label);
        if (const std::optional<double>& v = p.*field.member)
            std::printf("  %-18s %8.2f %s\n", label.c_str(), *v, std::string(field.unit).c_str());
        else
            std::printf("  %-18s %8s\n", label.c_str(), "-");
    }
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
