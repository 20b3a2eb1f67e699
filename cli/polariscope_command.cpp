// facetlight polariscope: the stone turned between crossed polarisers, as a gemmologist's first test of an
// unknown stone: does it stay dark (singly refracting) or blink four times a turn (doubly refracting)?
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "commands.h"
#include "cuts/mesh_resolver.h"
#include "image/image.h"
#include "pictures/polariscope_chart.h"
#include "pictures/webp_animation.h"
#include "scene/scene.h"
#include "terminal_output.h"
#include "trace_options.h"
#include "viewer/polariscope.h"

namespace facetlight::cli {

namespace {

struct PolariscopeOptions {
    TraceOptions trace;
    SettingsFlags polariscope;  // --angles, --polariscope-photons, --polariscope-picture
    std::string jsonPath;
    std::string outDir;
};

void run(const PolariscopeOptions& o) {
    const TraceSettings settings = toTraceSettings(o.trace);
    PolariscopeSettings instrument;
    o.polariscope.apply(polariscopeSettingsSchema(), instrument);
    if (o.outDir.empty()) instrument.pictureSize = 0;  // the view from above is drawn only to be written
    const Stone stone = resolveStone(o.trace.mesh, stoneOptions(o.trace));
    RunControl control;
    Polariscope p;
    {
        ProgressLine bar(true, control);
        control.startPhase(RunPhase::Tracing, uint64_t(instrument.angles) * instrument.photons);
        p = polariscope(stone, settings, instrument, &control);
    }
    nlohmann::json j = toJson(p);
    j["settings"] = toJson(settings);
    j["polariscope"] = polariscopeSettingsSchema().write(instrument);
    if (!o.jsonPath.empty()) writeFile(o.jsonPath, j.dump(2) + "\n");
    std::cout << "turned (deg)  through the analyser (share of the light leaving upward)\n";
    for (const PolariscopeReading& r : p.readings) {
        char line[96];
        std::snprintf(line, sizeof line, "%10.1f    %5.1f +- %.1f %%\n", r.angleDeg, 100 * r.share(),
                      100 * r.shareStderr());
        std::cout << line;
    }
    std::cout << polariscopeVerdict(p) << "\n";
    if (!o.outDir.empty()) {
        const std::filesystem::path out(o.outDir);
        std::filesystem::create_directories(out);
        writeFile(out / "polariscope.json", j.dump(2) + "\n");
        writeFile(out / "polariscope.png",
                  encodePng(polariscopeChart(p, "Polariscope: " + stone.name + ", " +
                                                    chooseMaterial(settings, stone).material.name())));
        if (instrument.pictureSize > 0)
            writeFile(out / "polariscope.webp",
                      encodeAnimatedWebp(polariscopeFrames(p), kPolariscopeFrameMs));
    }
}

}  // namespace

void addPolariscopeCommand(CLI::App& app) {
    auto o = std::make_shared<PolariscopeOptions>();
    o->trace.defaults.dispersion = false;
    CLI::App* cmd = app.add_subcommand(
        "polariscope",
        "Turn the stone between crossed polarisers, lit from below: does it blink? (--polariscope-photons per "
        "position; --photons is the trace's and unused here)");
    addTraceOptions(cmd, o->trace);
    o->polariscope.add(cmd, polariscopeSettingsSchema().fields(),
                       polariscopeSettingsSchema().write(PolariscopeSettings{}), "polariscope");
    cmd->add_option("--json", o->jsonPath, "Also write the readings as JSON to this file");
    cmd->add_option(
        "--out", o->outDir,
        "Write polariscope.json, the chart polariscope.png and the turning view polariscope.webp (not with "
        "--polariscope-picture 0) here");
    cmd->callback([o] { run(*o); });
}

}  // namespace facetlight::cli
