// facetlight trace: shoot photons at a stone and print the verdict and figures, or the statistics as JSON;
// with
// --colour also the face-up colour's figures (the picture is render --colour's).
#include <iostream>
#include <memory>
#include <sstream>

#include "commands.h"
#include "cuts/mesh_resolver.h"
#include "process_communicator.h"
#include "progress_json.h"
#include "settings_flags.h"
#include "stats_summary.h"
#include "terminal_output.h"
#include "trace/distributed_trace.h"
#include "trace/photon_tracer.h"
#include "trace_options.h"
#include "util/error.h"
#include "viewer/colour_view.h"
#include "viewer/verdict.h"

namespace facetlight::cli {

namespace {

struct TraceCommandOptions {
    TraceOptions trace;
    bool json = false;  // --json given: the statistics as JSON, to jsonPath or (none, "-") stdout
    std::string jsonPath;
    std::string csvPath;
    bool progressJson = false;
    ViewFlags<ColourSettings> colour;
};

void run(const TraceCommandOptions& o) {
    const TraceSettings settings = toTraceSettings(o.trace);
    const std::optional<ColourSettings> colour = o.colour.read();
    const Stone stone = resolveStone(o.trace.mesh, stoneOptions(o.trace));
    // Under mpirun the ranks split the blocks and rank 0 alone reports (docs/distributed.md).
    Communicator& comm = processCommunicator();
    const Scene scene(stone, settings);
    const TraceBase trace(scene, settings);
    RunControl control;
    control.startPhase(RunPhase::Tracing, localPhotons(comm, settings.photons));
    TraceResult result;
    nlohmann::json viewer, colourFigures;
    {
        const uint64_t viewing = 2 * viewerUnits(settings.viewer);
        ProgressLine bar(comm.isRoot() && !o.progressJson, control);
        ProgressJson progress(o.progressJson && comm.isRoot(), control, [&](RunPhase phase) {
            return phase == RunPhase::Tracing ? settings.photons : phase == RunPhase::Viewing ? viewing : 0;
        });
        result = traceDistributed(comm, trace, &control);
        // Rank 0 alone: the stone and the reference it is judged against, seen as a viewer sees them.
        if (comm.isRoot() && settings.viewer.enabled) {
            control.startPhase(RunPhase::Viewing, viewing);
            viewer = viewerReport(stone, settings, &control);
        }
        if (comm.isRoot() && colour) colourFigures = toJson(colourView(stone, settings, *colour, &control));
    }

    if (!comm.isRoot()) return;
    nlohmann::json stats = traceReport(result, stone, settings);
    addDesignFacts(stats, designFacts(stone, settings));
    if (comm.size() > 1) stats["timing"]["ranks"] = comm.size();
    if (!viewer.is_null()) stats["viewer"] = std::move(viewer);
    if (!colourFigures.is_null()) stats["colour"] = std::move(colourFigures);
    const bool jsonToStdout = o.json && (o.jsonPath.empty() || o.jsonPath == "-");
    if (jsonToStdout)
        std::cout << stats.dump(2) << "\n";
    else
        printStatsSummary(std::cout, stats);
    if (!jsonToStdout && stats.contains("colour")) printColourFigures(std::cout, stats["colour"]);
    if (o.json && !jsonToStdout) writeFile(o.jsonPath, stats.dump(2) + "\n");
    if (!o.csvPath.empty()) {
        std::ostringstream csv;
        writeFacetCsv(csv, result.stats, stone);
        writeFile(o.csvPath, csv.str());
    }
}

}  // namespace

void addTraceCommand(CLI::App& app) {
    auto o = std::make_shared<TraceCommandOptions>();
    CLI::App* cmd =
        app.add_subcommand("trace", "Trace photons through a stone and report per-facet light statistics");
    addTraceOptions(cmd, o->trace);
    CLI::Option* json =
        cmd->add_option(
               "--json", o->jsonPath,
               "Write the statistics as JSON to this file, or to stdout instead of the summary (no file, -)")
            ->expected(0, 1);
    cmd->add_option("--csv", o->csvPath, "Also write the facet table as CSV here");
    cmd->add_flag("--progress-json", o->progressJson,
                  "Write progress as JSON lines on stderr (for a parent process)");
    o->colour.add(cmd, "--colour",
                  "Also measure the stone's face-up colour under a CIE illuminant, absorbing at its size "
                  "(docs/optics.md), into the summary and stats colour (render --colour also draws it)",
                  colourSettingsSchema(), "colour");
    cmd->callback([o, json] {
        o->json = json->count() > 0;
        run(*o);
    });
}

}  // namespace facetlight::cli
