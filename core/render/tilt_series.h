#pragma once
// The stone rocked through a tilt series (docs/physics.md, "Tilt series and sparkle"): an ASET view per tilt,
// each frame's light return (the share of the face-up area lit by the sky: bright or low light) and the
// scintillation, the share of the face-up area that switches between lit and dark from one frame to the next.
//
// Every frame draws the same random streams (the job seed): a pixel whose light paths do not change with the
// tilt keeps its class, so switching measures the stone, not the noise.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "render/aset.h"

namespace facetlight {

struct TiltFrame {
    double tiltDeg = 0;  // added to the job's tilt
    AsetView view;
    AsetShare lightReturn;  // bright + low share of the rays that met the stone
};

struct TiltSeries {
    double axisDeg = 0;  // the azimuth of the axis the stone rocked about
    std::vector<TiltFrame> frames;
    // Pixels on the stone in both frames of a consecutive pair, and how many of them switched, over all
    // pairs.
    uint64_t pixelPairs = 0, switched = 0;
    bool cancelled = false;

    AsetShare scintillation() const;  // switched / pixelPairs, binomial standard error
};

// Frames of the scene's stone turned by settings.tiltDeg(k) about the horizontal axis at settings.axisDeg,
// after the job's own tilt, through `camera`; the trace's threads and seed. Advances control->done() by each
// frame's pixels.
TiltSeries tiltSeries(const TraceBase& trace, const CameraSettings& camera, int width, int height,
                      const AsetSettings& aset, const TiltSeriesSettings& settings,
                      RunControl* control = nullptr);

// "x", "y" or "the axis at 30 deg azimuth": the axis at azimuth `axisDeg`, for titles.
std::string tiltAxisName(double axisDeg);

// {"settings", "frames": [{"tilt_deg", "light_return", "light_return_stderr", "shares": {...}}],
//  "scintillation", "scintillation_stderr", "pixel_pairs"}
nlohmann::json toJson(const TiltSeries& series, const TiltSeriesSettings& settings);

}  // namespace facetlight
