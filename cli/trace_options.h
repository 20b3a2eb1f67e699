#pragma once
// The trace flags every photon-shooting subcommand takes: --mesh, and one flag per trace setting (made from
// traceSettingsSchema()), turned into TraceSettings in one place. Header-only: the CLI's build takes its
// sources from cli/*_command.cpp.
#include <algorithm>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "settings_flags.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"

namespace facetlight::cli {

// The CLI's defaults: the core's, with a thread per core.
inline TraceSettings defaultTraceSettings() {
    TraceSettings s;
    s.threads = int(std::max(1u, std::thread::hardware_concurrency()));
    return s;
}

struct TraceOptions {
    std::string mesh;
    bool keepFrame = false;  // --keep-frame: a mesh keeps its own orientation (docs/gemcad.md)
    SettingsFlags flags;
    TraceSettings defaults = defaultTraceSettings();  // what the flags not given take (a sweep: fewer photons)
};

// How --mesh is read into a stone.
inline StoneOptions stoneOptions(const TraceOptions& o) {
    StoneOptions options;
    options.keepFrame = o.keepFrame;
    return options;
}

// `withMesh` false: the subcommand makes its own stones (a sweep) and takes no --mesh.
inline void addTraceOptions(CLI::App* cmd, TraceOptions& o, bool withMesh = true) {
    if (withMesh) {
        cmd->add_option("--mesh", o.mesh, "OBJ, STL or GemCad .asc/.gem file, or a shipped shape name")->required();
        cmd->add_flag("--keep-frame", o.keepFrame,
                      "Keep a mesh's own orientation (GemCad designs always keep theirs; docs/gemcad.md)");
    }
    o.flags.add(cmd, traceSettingsSchema().fields(), toJson(o.defaults));
}

// Throws Error naming the flag at fault.
inline TraceSettings toTraceSettings(const TraceOptions& o) {
    TraceSettings s = o.defaults;
    o.flags.apply(traceSettingsSchema(), s);
    return s;
}

}  // namespace facetlight::cli
