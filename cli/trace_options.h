#pragma once
// The trace flags every photon-shooting subcommand takes: --mesh, and one flag per trace setting (made from
// traceSettingsSchema()), turned into TraceSettings in one place. Header-only: the CLI's build takes its
// sources from cli/*_command.cpp.
#include <algorithm>
#include <string>
#include <thread>

#include <CLI/CLI.hpp>

#include "settings_flags.h"
#include "trace/trace_settings.h"

namespace facetlight::cli {

struct TraceOptions {
    std::string mesh;
    SettingsFlags flags;
};

// The CLI's defaults: the core's, with a thread per core.
inline TraceSettings defaultTraceSettings() {
    TraceSettings s;
    s.threads = int(std::max(1u, std::thread::hardware_concurrency()));
    return s;
}

inline void addTraceOptions(CLI::App* cmd, TraceOptions& o) {
    cmd->add_option("--mesh", o.mesh, "OBJ, STL or GemCad .asc file, or a shipped shape name")->required();
    o.flags.add(cmd, traceSettingsSchema().fields(), toJson(defaultTraceSettings()));
}

// Throws Error naming the flag at fault.
inline TraceSettings toTraceSettings(const TraceOptions& o) {
    TraceSettings s = defaultTraceSettings();
    o.flags.apply(traceSettingsSchema(), s);
    return s;
}

}  // namespace facetlight::cli
