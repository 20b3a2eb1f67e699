// facetlight doubling: the stone seen face-up through a loupe, its pavilion's edges doubled by a doubly
// refracting stone, as a gemmologist tells moissanite from diamond: how far apart the two images are.
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "cuts/mesh_resolver.h"
#include "image/image.h"
#include "pictures/doubling_picture.h"
#include "terminal_output.h"
#include "trace_options.h"
#include "viewer/doubling.h"

namespace facetlight::cli {

namespace {

struct DoublingOptions {
    TraceOptions trace;
    SettingsFlags doubling;  // --doubling-picture, --doubling-tilt, --loupe
    std::string jsonPath;
    std::string outDir;
};

void run(const DoublingOptions& o) {
    const TraceSettings settings = toTraceSettings(o.trace);
    DoublingSettings view;
    o.doubling.apply(doublingSettingsSchema(), view);
    const Stone stone = resolveStone(o.trace.mesh, stoneOptions(o.trace));
    const Doubling d = doubling(stone, settings, view);
    nlohmann::json j = toJson(d);
    j["settings"] = toJson(settings);
    j["doubling"] = doublingSettingsSchema().write(view);
    if (!o.jsonPath.empty()) writeFile(o.jsonPath, j.dump(2) + "\n");
    std::cout << doublingTitle(stone, settings) << "\n" << doublingSummary(d) << "\n";
    if (!o.outDir.empty()) {
        const std::filesystem::path out(o.outDir);
        std::filesystem::create_directories(out);
        writeFile(out / "doubling.json", j.dump(2) + "\n");
        writeFile(out / "doubling.png", encodePng(doublingPicture(d, doublingTitle(stone, settings))));
    }
}

}  // namespace

void addDoublingCommand(CLI::App& app) {
    auto o = std::make_shared<DoublingOptions>();
    o->trace.defaults.dispersion = false;
    CLI::App* cmd = app.add_subcommand("doubling",
                                       "The stone face-up through a loupe: how far apart a doubly refracting "
                                       "stone shows the two images of its "
                                       "pavilion's edges (--photons is the trace's and unused here)");
    addTraceOptions(cmd, o->trace);
    o->doubling.add(cmd, doublingSettingsSchema().fields(),
                    doublingSettingsSchema().write(DoublingSettings{}), "doubling");
    cmd->add_option("--json", o->jsonPath, "Also write the measurement as JSON to this file");
    cmd->add_option("--out", o->outDir, "Write doubling.json and the face-up picture doubling.png here");
    cmd->callback([o] { run(*o); });
}

}  // namespace facetlight::cli
