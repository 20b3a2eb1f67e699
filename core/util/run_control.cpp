#include "util/run_control.h"

#include <array>
#include <utility>

namespace facetlight {
namespace {

// The names progress is reported under (the CLI's JSON lines, the service's job status).
constexpr std::array<std::pair<RunPhase, std::string_view>, 6> kPhaseNames{
    {{RunPhase::Queued, "queued"},
     {RunPhase::Tracing, "tracing"},
     {RunPhase::Viewing, "viewing"},
     {RunPhase::PhotonMap, "photon_map"},
     {RunPhase::Rendering, "rendering"},
     {RunPhase::Done, "done"}}};

}  // namespace

std::string_view runPhaseName(RunPhase phase) {
    for (const auto& [p, name] : kPhaseNames)
        if (p == phase) return name;
    return "queued";
}

std::optional<RunPhase> runPhaseNamed(std::string_view name) {
    for (const auto& [p, n] : kPhaseNames)
        if (n == name) return p;
    return std::nullopt;
}

}  // namespace facetlight
