#pragma once
// A study is what a job asks for: trace photons through a stone for the statistics, then (optionally) build
// the photon maps and render the pictures. The CLI's `render` and the service's job worker both run one.
#include <atomic>
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "render/render_settings.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/distributed.h"

namespace facetlight {

struct StudySettings {
    TraceSettings trace;
    std::optional<RenderSettings> render;  // none: statistics only
};

enum class StudyPhase : int { Queued, Tracing, PhotonMap, Rendering, Done };
std::string_view studyPhaseName(StudyPhase phase);

// Shared with whoever watches the study: progress is read, cancel is set, from any thread.
struct StudyControl {
    std::atomic<StudyPhase> phase{StudyPhase::Queued};
    std::atomic<uint64_t> done{0};  // units of the current phase: photons, or pixels
    std::atomic<uint64_t> total{0};
    std::atomic<bool> cancel{false};
};

struct StudyResult {
    nlohmann::json stats;                           // the statistics document (docs/stats-schema.md)
    std::string statsCsv;                           // the facet table
    std::string renderPng, heatmapPng, angularPng;  // empty without a render (the heat-map: always)
    std::string heatmapLayout;  // heatmap.png's facets in pixels (JSON, docs/stats-schema.md), with it
};

// Throws Canceled when control.cancel is set while it runs, Error on bad settings.
StudyResult runStudy(const Stone& stone, const StudySettings& settings, StudyControl& control);
// The same on every rank of `comm` (docs/distributed.md): the trace, the map photons and the render's tiles
// are split across the ranks and rank 0's result equals the single-process one apart from `timing`; the other
// ranks return empty results. control.done and control.total count this rank's share of each phase.
StudyResult runStudy(const Stone& stone, const StudySettings& settings, StudyControl& control,
                     Communicator& comm);

class Canceled : public std::exception {
  public:
    const char* what() const noexcept override { return "canceled"; }
};

}  // namespace facetlight
