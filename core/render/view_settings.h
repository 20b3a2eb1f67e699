#pragma once
// The inputs of the viewer's views (docs/physics.md, "ASET view" and "Tilt series and sparkle"): the ASET
// picture's angles and samples, and the tilt series. Apart from the algorithms (render/aset.h,
// render/tilt_series.h), each setting described once in its table: JSON, checks, CLI flags and the API
// schema follow from it.
#include <nlohmann/json.hpp>

#include "settings/settings_schema.h"

namespace facetlight {

// Where the light that reaches the viewer comes from, by its direction before it entered the stone. The
// defaults are the AGS ASET's bands: blue 75-90 deg elevation (the viewer's head), red 45-75, green 0-45,
// below the horizon leakage (docs/physics.md cites the sources).
struct AsetSettings {
    double headConeDeg = 15;    // half-angle of the viewer's head cone around the direction to the viewer
    double lowBelowDeg = 45;    // elevation below which light counts as low (green), above as bright (red)
    int samples = 8;            // view rays per pixel, each followed one way at every facet
    bool whiteLeakage = false;  // leakage drawn white (ASET on a white ground) instead of black

    void validate() const;  // throws Error naming the field ("aset.samples")
    static AsetSettings fromJson(const nlohmann::json& j);
};

// The stone rocked from -maxDeg to +maxDeg in steps of stepDeg about the horizontal world axis at azimuth
// axisDeg (0: the x axis, the picture's horizontal axis face-up; 90: the y axis, its vertical axis).
struct TiltSeriesSettings {
    double maxDeg = 10;
    double stepDeg = 1;
    double axisDeg = 0;

    double frameCount() const;  // 2 * floor(maxDeg / stepDeg) + 1, however many
    int frames() const;         // frameCount() of validated settings: at most kMaxTiltFrames
    double tiltDeg(int frame) const;
    void validate() const;  // throws Error naming the field ("tilt_series.step_deg")
    static TiltSeriesSettings fromJson(const nlohmann::json& j);
};

constexpr int kMaxAsetSamples = 64;
constexpr double kMaxTiltDeg = 45;  // the tilt sweeps the field uses (Sasian et al. 2007: up to +-45 deg)
constexpr int kMaxTiltFrames = 181;

// Their paths start with "aset." and "tilt_series.", where a job holds them.
const settings::Schema<AsetSettings>& asetSettingsSchema();
const settings::Schema<TiltSeriesSettings>& tiltSeriesSettingsSchema();
nlohmann::json toJson(const AsetSettings& s);
nlohmann::json toJson(const TiltSeriesSettings& s);

}  // namespace facetlight
