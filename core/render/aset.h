#pragma once
// The ASET view (docs/physics.md, "ASET view"): the stone as the render's camera sees it, each pixel's view
// rays traced back through the stone to the direction their light came from, and classed by that direction:
// the viewer's head cone, bright light above `lowBelowDeg` elevation, low light below it, leakage from below
// the horizon, or trapped (the tracer's bounce limit).
//
// A view ray is a photon's path run backwards (reciprocity): it takes the tracer's one-photon step
// (PhotonWalker::step), choosing reflection or refraction at each facet with the Fresnel probabilities
// (Russian roulette), so each class's share of a pixel's rays estimates the share of its light from that
// part of the sky. Sample s of pixel p draws from Rng(seed, p * samples + s) alone: the view is the same bits
// for any thread count.
#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/render_settings.h"
#include "render/view_settings.h"
#include "trace/trace_base.h"
#include "util/run_control.h"

namespace facetlight {

enum class AsetClass : uint8_t { Head, Bright, Low, Leakage, Trapped };
constexpr int kAsetClasses = 5;
std::string_view asetClassName(AsetClass c);  // "head", "bright", "low", "leakage", "trapped"

// A share of the view rays that met the stone, with its binomial standard error sqrt(p (1 - p) / N).
struct AsetShare {
    double share = 0, standardError = 0;
};

struct AsetView {
    int width = 0, height = 0, samples = 0;
    // Per pixel, row by row from the top: how many of its view rays ended in each class; the rest missed the
    // stone.
    std::vector<std::array<uint8_t, kAsetClasses>> counts;
    std::array<uint64_t, kAsetClasses> totals{};  // over all pixels
    bool cancelled = false;

    uint64_t stoneRays() const;  // view rays that met the stone: the face-up area, in rays
    AsetShare share(AsetClass c) const;
    // The pixel's rays that came from the lit sky (bright or low light) against those that did not (head,
    // leakage, trapped); false for a pixel off the stone.
    bool onStone(size_t pixel) const;
    bool lit(size_t pixel) const;
};

// The stone turned by `deg` about the horizontal world axis at azimuth `axisDeg` (0: x, 90: y) through the
// origin of its frame, after the scene's own tilt: a tilt series' frame, every frame sharing one Scene.
struct StoneTurn {
    double deg = 0, axisDeg = 0;
};

// The view through `camera` at width x height pixels, of the scene's stone turned by `turn`. Advances
// control->done() by the pixels of each row. Throws Error on bad settings.
AsetView asetView(const TraceBase& trace, const CameraSettings& camera, int width, int height,
                  const AsetSettings& settings, int threads, uint64_t seed, RunControl* control = nullptr,
                  const StoneTurn& turn = {});

// {"settings", "rays" (that met the stone), "shares": {class: {"share", "stderr"}}}
nlohmann::json toJson(const AsetView& view, const AsetSettings& settings);

}  // namespace facetlight
