#include "render/view_settings.h"

#include <cmath>
#include <set>
#include <string>

#include "util/error.h"
#include "util/settings_schema.h"

namespace facetlight {
namespace {

using nlohmann::json;

// Refuses a non-object and any key not in `known`, naming the field.
void checkKeys(const json& j, const std::string& path, const std::set<std::string>& known) {
    if (!j.is_object()) throw Error(path, path + " must be an object");
    for (const auto& [key, value] : j.items()) {
        const std::string field = settings::fieldPath(path, key);
        if (!known.count(key)) throw Error(field, "unknown field '" + field + "'");
    }
}

double number(const json& j, const std::string& field) {
    return settings::readNumber(j, field, {});
}

}  // namespace

void AsetSettings::validate() const {
    if (!(headConeDeg >= 0 && headConeDeg < 90)) {
        throw Error("aset.head_cone_deg", "aset.head_cone_deg must be a number from 0 to below 90");
    }
    if (!(lowBelowDeg >= 0 && lowBelowDeg <= 90))
        throw Error("aset.low_below_deg", "aset.low_below_deg must be a number from 0 to 90");
    if (samples < 1 || samples > kMaxAsetSamples) {
        throw Error("aset.samples",
                    "aset.samples must be an integer between 1 and " + std::to_string(kMaxAsetSamples));
    }
}

AsetSettings AsetSettings::fromJson(const json& j) {
    checkKeys(j, "aset", {"head_cone_deg", "low_below_deg", "samples", "white_leakage"});
    AsetSettings s;
    if (j.contains("head_cone_deg")) s.headConeDeg = number(j["head_cone_deg"], "aset.head_cone_deg");
    if (j.contains("low_below_deg")) s.lowBelowDeg = number(j["low_below_deg"], "aset.low_below_deg");
    if (j.contains("samples"))
        s.samples = int(settings::readCount(j["samples"], "aset.samples", 1, kMaxAsetSamples));
    if (j.contains("white_leakage"))
        s.whiteLeakage = settings::readBool(j["white_leakage"], "aset.white_leakage");
    s.validate();
    return s;
}

int TiltSeriesSettings::frames() const {
    return 2 * int(std::floor(maxDeg / stepDeg + 1e-9)) + 1;
}

double TiltSeriesSettings::tiltDeg(int frame) const {
    return (frame - (frames() - 1) / 2) * stepDeg;
}

void TiltSeriesSettings::validate() const {
    if (!(maxDeg > 0 && maxDeg <= kMaxTiltDeg)) {
        throw Error("tilt_series.max_deg",
                    "tilt_series.max_deg must be a number above 0 up to " + std::to_string(int(kMaxTiltDeg)));
    }
    if (!(stepDeg > 0 && stepDeg <= maxDeg)) {
        throw Error("tilt_series.step_deg",
                    "tilt_series.step_deg must be a number above 0 up to tilt_series.max_deg");
    }
    if (frames() > kMaxTiltFrames) {
        throw Error("tilt_series.step_deg", "tilt_series: " + std::to_string(frames()) +
                                                " frames, more than " + std::to_string(kMaxTiltFrames) +
                                                "; raise tilt_series.step_deg");
    }
}

TiltSeriesSettings TiltSeriesSettings::fromJson(const json& j) {
    checkKeys(j, "tilt_series", {"max_deg", "step_deg"});
    TiltSeriesSettings s;
    if (j.contains("max_deg")) s.maxDeg = number(j["max_deg"], "tilt_series.max_deg");
    if (j.contains("step_deg")) s.stepDeg = number(j["step_deg"], "tilt_series.step_deg");
    s.validate();
    return s;
}

json toJson(const AsetSettings& s) {
    return {{"head_cone_deg", s.headConeDeg},
            {"low_below_deg", s.lowBelowDeg},
            {"samples", s.samples},
            {"white_leakage", s.whiteLeakage}};
}

json toJson(const TiltSeriesSettings& s) {
    return {{"max_deg", s.maxDeg}, {"step_deg", s.stepDeg}};
}

}  // namespace facetlight
