#include "render/render_settings.h"

#include <cmath>
#include <set>
#include <string>

#include "trace/trace_settings.h"
#include "util/error.h"
#include "util/json_fields.h"

namespace facetlight {
namespace {

using nlohmann::json;
using namespace json_fields;

double getNumberIn(const json& j, const std::string& field, double lo, double hi, bool openLo = false) {
    const std::string range = field + " must be a number " + (openLo ? "above " : "from ") +
                              std::to_string(int(lo)) + (openLo ? " up to " : " to ") +
                              std::to_string(int(hi));
    if (!j.is_number()) throw Error(range);
    const double v = j.get<double>();
    if (!(openLo ? v > lo : v >= lo) || !(v <= hi)) throw Error(range);
    return v;
}

}  // namespace

void RenderSettings::validate() const {
    auto side = [](int v, const char* field) {
        if (v < kMinImageSide || v > kMaxImageSide) {
            throw Error(std::string(field) + " must be an integer between " + std::to_string(kMinImageSide) +
                        " and " + std::to_string(kMaxImageSide));
        }
    };
    side(width, "render.width");
    side(height, "render.height");
    if (samples < 1 || samples > kMaxSamples) {
        throw Error("render.samples must be an integer between 1 and " + std::to_string(kMaxSamples));
    }
    if (maxDepth < 1 || maxDepth > kMaxDepth) {
        throw Error("render.max_depth must be an integer between 1 and " + std::to_string(kMaxDepth));
    }
    if (mapPhotons < 1000 || mapPhotons > kMaxPhotons) {
        throw Error("render.map_photons must be an integer between 1000 and " + std::to_string(kMaxPhotons));
    }
    if (!(camera.elevationDeg >= -90 && camera.elevationDeg <= 90)) {
        throw Error("render.camera.elevation_deg must be a number from -90 to 90");
    }
    if (!(camera.azimuthDeg >= -360 && camera.azimuthDeg <= 360)) {
        throw Error("render.camera.azimuth_deg must be a number from -360 to 360");
    }
    if (!(camera.distance >= kMinCameraDistance && camera.distance <= kMaxCameraDistance)) {
        throw Error("render.camera.distance must be a number from 1 to 1000 (girdle diameters)");
    }
    if (!(camera.fovDeg > 0 && camera.fovDeg <= kMaxFovDeg)) {
        throw Error("render.camera.fov_deg must be a number above 0 up to 120");
    }
}

RenderSettings RenderSettings::fromJson(const json& j) {
    checkKeys(j, "render", {"width", "height", "samples", "max_depth", "map_photons", "camera"});
    RenderSettings s;
    if (j.contains("width"))
        s.width = int(getCount(j["width"], "render.width", kMinImageSide, kMaxImageSide));
    if (j.contains("height"))
        s.height = int(getCount(j["height"], "render.height", kMinImageSide, kMaxImageSide));
    if (j.contains("samples")) s.samples = int(getCount(j["samples"], "render.samples", 1, kMaxSamples));
    if (j.contains("max_depth")) s.maxDepth = int(getCount(j["max_depth"], "render.max_depth", 1, kMaxDepth));
    if (j.contains("map_photons")) {
        s.mapPhotons = getCount(j["map_photons"], "render.map_photons", 1000, kMaxPhotons);
    }
    if (j.contains("camera")) {
        const json& c = j["camera"];
        checkKeys(c, "render.camera", {"elevation_deg", "azimuth_deg", "distance", "fov_deg"});
        if (c.contains("elevation_deg")) {
            s.camera.elevationDeg = getNumberIn(c["elevation_deg"], "render.camera.elevation_deg", -90, 90);
        }
        if (c.contains("azimuth_deg")) {
            s.camera.azimuthDeg = getNumberIn(c["azimuth_deg"], "render.camera.azimuth_deg", -360, 360);
        }
        if (c.contains("distance")) {
            s.camera.distance =
                getNumberIn(c["distance"], "render.camera.distance", kMinCameraDistance, kMaxCameraDistance);
        }
        if (c.contains("fov_deg"))
            s.camera.fovDeg = getNumberIn(c["fov_deg"], "render.camera.fov_deg", 0, kMaxFovDeg, true);
    }
    s.validate();
    return s;
}

nlohmann::json toJson(const RenderSettings& s) {
    return {{"width", s.width},
            {"height", s.height},
            {"samples", s.samples},
            {"max_depth", s.maxDepth},
            {"map_photons", s.mapPhotons},
            {"camera",
             {{"elevation_deg", s.camera.elevationDeg},
              {"azimuth_deg", s.camera.azimuthDeg},
              {"distance", s.camera.distance},
              {"fov_deg", s.camera.fovDeg}}}};
}

}  // namespace facetlight
