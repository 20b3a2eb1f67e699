#pragma once
// What the subcommands write: result files, and a one-line progress display on stderr while work runs
// (header-only: the CLI's build takes its sources from cli/*_command.cpp).
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <string>
#include <string_view>
#include <thread>
#include <utility>

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
        std::snprintf(line, sizeof line, "  %-8s %6.2f%% +- %.2f\n", name.c_str(),
                      100 * s["share"].get<double>(), 100 * s["stderr"].get<double>());
        out << line;
    }
}

// The colour view's figures ("colour" in docs/stats-schema.md): CIELAB mean and spread, the area's shares.
inline void printColourFigures(std::ostream& out, const nlohmann::json& c) {
    out << "Face-up colour under " << c["illuminant"].get<std::string>() << " at "
        << c["size_mm"].get<double>() << " mm (" << c["pixels"].get<uint64_t>() << " pixels, "
        << c["rays"].get<uint64_t>() << " view rays):\n";
    for (const char* f : {"L", "a", "b", "chroma"}) {
        const nlohmann::json& v = c[f];
        char line[128];
        std::snprintf(line, sizeof line, "  %-8s %7.2f +- %.2f   spread %6.2f +- %.2f\n", f,
                      v["mean"].get<double>(), v["mean_stderr"].get<double>(), v["spread"].get<double>(),
                      v["spread_stderr"].get<double>());
        out << line;
    }
    const nlohmann::json& m = c["mean_colour"];
    char line[128];
    std::snprintf(line, sizeof line, "  mean colour L* %.2f a* %.2f b* %.2f (%s)\n", m["L"].get<double>(),
                  m["a"].get<double>(), m["b"].get<double>(), m["srgb"].get<std::string>().c_str());
    out << line;
    for (const char* f : {"windowed", "extinct", "saturated"}) {
        std::snprintf(line, sizeof line, "  %-9s %6.2f%% +- %.2f\n", f, 100 * c[f]["share"].get<double>(),
                      100 * c[f]["stderr"].get<double>());
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

// The progress line's text: in a staged run (a sweep's rounds) "round 2 of 4: 12 of 25 points", else the
// phase; then a bar of that step and, once a tenth of it is done, the time it has left at its pace so far.
inline std::string progressText(const RunControl& control, double stepSeconds) {
    constexpr int kWidth = 30;
    std::string label;
    double share = 0;
    if (const int stage = control.stage(); stage > 0) {
        const uint64_t done = control.itemsDone(), total = control.itemsTotal();
        label = "round " + std::to_string(stage) + " of " + std::to_string(control.stages()) + ": " +
                std::to_string(done) + " of " + std::to_string(total) + (total == 1 ? " point" : " points");
        share = total ? double(done) / double(total) : 0.0;
    } else {
        label = std::string(runPhaseName(control.phase()));
        share = control.fraction();
    }
    share = std::clamp(share, 0.0, 1.0);
    const int filled = int(share * kWidth);
    std::string text = label + " [" + std::string(filled, '#') + std::string(kWidth - filled, ' ') + "] " +
                       std::to_string(int(100 * share)) + "%";
    if (share >= 0.1 && share < 1) {
        const double left = stepSeconds * (1 - share) / share;
        text += left < 90 ? ", about " + std::to_string(int(left + 0.5)) + " s left"
                          : ", about " + std::to_string(int(left / 60 + 0.5)) + " min left";
    }
    return text;
}

// Redraws progressText on stderr every 100 ms while it lives, only when stderr is a terminal and `wanted`.
class ProgressLine {
  public:
    ProgressLine(bool wanted, const RunControl& control) {
        if (!wanted || !isatty(STDERR_FILENO)) return;
        thread_ = std::thread([this, &control] {
            // A step is a phase, or a round of a staged run: its clock starts when it does.
            auto stepStart = std::chrono::steady_clock::now();
            std::pair<RunPhase, int> step{control.phase(), control.stage()};
            while (!finished_.load()) {
                const std::pair<RunPhase, int> now{control.phase(), control.stage()};
                if (now.second > 0 ? now.second != step.second : now != step)
                    stepStart = std::chrono::steady_clock::now();
                step = now;
                const double seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - stepStart).count();
                std::fprintf(stderr, "\r%-72s", progressText(control, seconds).c_str());
                std::fflush(stderr);
                std::this_thread::sleep_for(std::chrono::milliseconds(100));
            }
            std::fprintf(stderr, "\r%72s\r", "");
        });
    }
    ~ProgressLine() {
        finished_ = true;
        if (thread_.joinable()) thread_.join();
    }
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

  private:
    std::atomic<bool> finished_{false};
    std::thread thread_;
};

}  // namespace facetlight::cli
