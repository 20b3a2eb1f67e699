#pragma once
// What a viewer sees of a stone (docs/physics.md, "Viewer figures"): brightness, contrast, scintillation,
// windowing and extinction in the office, fire under the spot lights, each with its standard error, and the
// face-up measures the faults are recognised by (viewer/verdict.h).
#include <array>
#include <cstdint>
#include <string_view>

#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/run_control.h"
#include "viewer/office_view.h"
#include "viewer/spot_fire.h"

namespace facetlight {

struct ViewerFigure {
    double value = 0, stderr = 0;
};

struct ViewerFigures {
    OfficeTally office;
    SpotTally spot;
    bool cancelled = false;

    ViewerFigure brightness() const;     // mean radiance seen over the face-up area, relative to the zenith's
    ViewerFigure fire() const;           // share of the lamps' photons seen as colour
    ViewerFigure contrast() const;       // share of the face-up area that shows the viewer (head, shoulders)
    ViewerFigure scintillation() const;  // share of the face-up area that switches lit/dark in a sparkle step
    ViewerFigure windowing() const;      // share of the face-up area that shows the tray through the stone
    ViewerFigure extinction() const;     // share of the face-up area dark throughout a rock
    // Face-up measures: of the table's area, the share that shows the girdle (fish-eye) and the share that
    // shows the tray through the stone; of the table's centre, the share that shows the viewer's head
    // (nail-head); how much darker the middle slice across the width is than the slices either side of it
    // (bow-tie).
    ViewerFigure girdleInTable() const;
    ViewerFigure seeThroughTable() const;
    ViewerFigure headInTableCentre() const;
    ViewerFigure darkMiddle() const;
};

// The figures, in the order tables show them; `higherIsBetter` false for the ones a viewer wants little of.
struct ViewerFigureInfo {
    std::string_view key, label, setUp;
    ViewerFigure (ViewerFigures::*get)() const;
    bool higherIsBetter;
};
inline constexpr std::array<ViewerFigureInfo, 6> kViewerFigures{{
    {"brightness", "brightness", "office", &ViewerFigures::brightness, true},
    {"fire", "fire", "spot", &ViewerFigures::fire, true},
    {"scintillation", "scintillation", "office", &ViewerFigures::scintillation, true},
    {"contrast", "contrast", "office", &ViewerFigures::contrast, true},
    {"windowing", "windowing", "office", &ViewerFigures::windowing, false},
    {"extinction", "extinction", "office", &ViewerFigures::extinction, false},
}};
// The figure named `key`; null for any other name.
const ViewerFigureInfo* findViewerFigure(std::string_view key);

// Both set-ups of `trace.viewer` on `stone` with the job's scene (material, index, dispersion, size), seed,
// threads and bounce limit; the job's light plays no part. Advances control->done() by viewerUnits(); throws
// Error on bad settings.
ViewerFigures viewStone(const Stone& stone, const TraceSettings& trace, RunControl* control = nullptr);
// The view rays and photons viewStone traces: its units of progress.
uint64_t viewerUnits(const ViewerSettings& settings);

}  // namespace facetlight
