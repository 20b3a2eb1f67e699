#pragma once
// The trace flags every photon-shooting subcommand takes (--mesh, --photons, --threads, --light, ...), added
// to a CLI11 subcommand and turned into validated TraceSettings in one place (header-only: the CLI's build
// takes its sources from cli/*_command.cpp).
#include <cmath>
#include <optional>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "trace/trace_settings.h"
#include "util/error.h"

namespace facetlight::cli {

struct TraceOptions {
    std::string mesh;
    std::string photons = "1e6";
    int threads = int(std::max(1u, std::thread::hardware_concurrency()));
    uint64_t seed = 1;
    std::string light = "collimated";
    double tilt = 0;
    double headShadow = 0;
    std::string material = "diamond";
    std::optional<double> n;
    bool noDispersion = false;
    int maxBounces = 64;
    std::string intersector = "auto";
};

// "1e6" and "1000000" alike, a whole number in [lo, hi]; `flag` names it in the error.
inline uint64_t parseCount(const std::string& text, const std::string& flag, uint64_t lo, uint64_t hi) {
    size_t used = 0;
    double v = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used == 0 || used != text.size() || !(v >= double(lo) && v <= double(hi)) || v != std::floor(v)) {
        throw Error(flag + " must be a whole number between " + std::to_string(lo) + " and " +
                    std::to_string(hi) + " (got '" + text + "')");
    }
    return uint64_t(v);
}

// `withMesh` false: the subcommand makes its own stones (a sweep) and takes no --mesh.
inline void addTraceOptions(CLI::App* cmd, TraceOptions& o, bool withMesh = true) {
    if (withMesh)
        cmd->add_option("--mesh", o.mesh, "OBJ, STL or GemCad .asc file, or a shipped shape name")->required();
    cmd->add_option("--photons", o.photons, "Photons to shoot, e.g. 1e6 or 1000000")->capture_default_str();
    cmd->add_option("--threads", o.threads, "Worker threads")->capture_default_str();
    cmd->add_option("--seed", o.seed, "Random seed; the same seed gives the same results")
        ->capture_default_str();
    cmd->add_option("--light", o.light, "collimated, hemisphere or point")->capture_default_str();
    cmd->add_option("--tilt", o.tilt, "Tilt of the stone about the x axis, degrees")->capture_default_str();
    cmd->add_option("--head-shadow", o.headShadow,
                    "Hemisphere: half-angle of the viewer's cone removed, degrees");
    cmd->add_option("--material", o.material, "diamond, cubic_zirconia, sapphire, fused_silica or bk7")
        ->capture_default_str();
    cmd->add_option("--n", o.n, "A constant refractive index instead of the material's");
    cmd->add_flag("--no-dispersion", o.noDispersion, "Trace every photon at 589.3 nm");
    cmd->add_option("--max-bounces", o.maxBounces, "Internal reflections before a photon counts as trapped")
        ->capture_default_str();
    cmd->add_option("--intersector", o.intersector, "auto, convex or embree")->capture_default_str();
}

// Throws Error naming the flag at fault.
inline TraceSettings toTraceSettings(const TraceOptions& o) {
    TraceSettings s;
    s.photons = parseCount(o.photons, "--photons", 1, kMaxPhotons);
    s.threads = o.threads;
    s.seed = o.seed;
    s.material = o.material;
    s.n = o.n;
    s.dispersion = !o.noDispersion;
    s.maxBounces = o.maxBounces;
    s.intersector = parseIntersector(o.intersector);
    s.light.model = parseLightModel(o.light);
    s.light.tiltDeg = o.tilt;
    s.light.headShadowDeg = o.headShadow;
    s.validate();
    return s;
}

}  // namespace facetlight::cli
