#include "render/view_settings.h"

#include <cmath>
#include <string>

#include "util/error.h"

namespace facetlight {

using namespace settings;

const Schema<AsetSettings>& asetSettingsSchema() {
    static const Schema<AsetSettings> schema({
        number("head_cone_deg", &AsetSettings::headConeDeg, {.lo = 0, .hi = 90, .openHi = true},
               {"--aset-head-cone", "ASET: half-angle of the viewer's head cone (blue)", "degrees"}),
        number("low_below_deg", &AsetSettings::lowBelowDeg, {.lo = 0, .hi = 90},
               {"--aset-low-below", "ASET: elevation below which light is low (green), above it bright (red)",
                "degrees"}),
        count("samples", &AsetSettings::samples, 1, kMaxAsetSamples,
              {"--aset-samples", "ASET: view rays per pixel"}),
        boolean("white_leakage", &AsetSettings::whiteLeakage,
                {"--aset-white-leakage", "ASET: draw leakage white, not black"}),
    });
    return schema;
}

const Schema<TiltSeriesSettings>& tiltSeriesSettingsSchema() {
    static const Schema<TiltSeriesSettings> schema(
        {
            number(
                "max_deg", &TiltSeriesSettings::maxDeg, {.lo = 0, .hi = kMaxTiltDeg, .openLo = true},
                {"--tilt-series",
                 "Tilt series (off unless a --tilt-... flag is given): rock the stone from -DEG to +DEG in "
                 "ASET views: tilt.webp (animation), tilt.png (light return against tilt) and the "
                 "scintillation (--stone-tilt tilts the stone itself for the whole study)",
                 "degrees"}),
            number("step_deg", &TiltSeriesSettings::stepDeg, {.lo = 0, .hi = kMaxTiltDeg, .openLo = true},
                   {"--tilt-step", "Tilt series: the step between frames", "degrees"}),
            number("axis_deg", &TiltSeriesSettings::axisDeg, {.lo = -360, .hi = 360},
                   {"--tilt-axis",
                    "Tilt series: azimuth of the horizontal axis the stone rocks about (0: x, the picture's "
                    "horizontal axis face-up; 90: y)",
                    "degrees"}),
        },
        [](const TiltSeriesSettings& s, const std::string& path) {
            const std::string step = fieldPath(path, "step_deg");
            if (s.stepDeg > s.maxDeg)
                throw Error(step, step + " must be no more than " + fieldPath(path, "max_deg"));
            // Counted in double before any conversion: a step of 1e-9 deg gives 9e10 frames, which an int
            // does not hold (issue 31).
            if (const double frames = s.frameCount(); !(frames <= kMaxTiltFrames)) {
                const std::string count = frames < 1e9 ? std::to_string(int64_t(frames)) : "over a billion";
                throw Error(step, step + " gives " + count + " frames, more than " +
                                      std::to_string(kMaxTiltFrames) + ": raise it");
            }
        });
    return schema;
}

// The tables' checks, for settings made in code.
void AsetSettings::validate() const {
    fromJson(toJson(*this));
}

AsetSettings AsetSettings::fromJson(const nlohmann::json& j) {
    return asetSettingsSchema().read(j, "aset");
}

double TiltSeriesSettings::frameCount() const {
    return 2 * std::floor(maxDeg / stepDeg + 1e-9) + 1;
}

int TiltSeriesSettings::frames() const {
    return int(frameCount());
}

double TiltSeriesSettings::tiltDeg(int frame) const {
    return (frame - (frames() - 1) / 2) * stepDeg;
}

void TiltSeriesSettings::validate() const {
    fromJson(toJson(*this));
}

TiltSeriesSettings TiltSeriesSettings::fromJson(const nlohmann::json& j) {
    return tiltSeriesSettingsSchema().read(j, "tilt_series");
}

nlohmann::json toJson(const AsetSettings& s) {
    return asetSettingsSchema().write(s);
}

nlohmann::json toJson(const TiltSeriesSettings& s) {
    return tiltSeriesSettingsSchema().write(s);
}

}  // namespace facetlight
