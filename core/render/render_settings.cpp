#include "render/render_settings.h"

#include "trace/trace_settings.h"

namespace facetlight {
namespace {

using namespace settings;

const Schema<CameraSettings>& cameraSchema() {
    static const Schema<CameraSettings> schema({
        number("elevation_deg", &CameraSettings::elevationDeg, {.lo = -90, .hi = 90},
               {"--elevation", "Camera elevation (90: face-up)", "degrees"}),
        number("azimuth_deg", &CameraSettings::azimuthDeg, {.lo = -360, .hi = 360},
               {"--azimuth", "Camera azimuth", "degrees"}),
        number("distance", &CameraSettings::distance, {.lo = 1, .hi = 1000},
               {"--distance", "Camera distance from the stone's centre", "girdle diameters"}),
        number("fov_deg", &CameraSettings::fovDeg, {.lo = 0, .hi = 120, .openLo = true},
               {"--fov", "Vertical field of view", "degrees"}),
    });
    return schema;
}

}  // namespace

const Schema<RenderSettings>& renderSettingsSchema() {
    static const Schema<RenderSettings> schema({
        count("width", &RenderSettings::width, kMinImageSide, kMaxImageSide,
              {"--width", "Image width", "pixels"}),
        count("height", &RenderSettings::height, kMinImageSide, kMaxImageSide,
              {"--height", "Image height", "pixels"}),
        count("samples", &RenderSettings::samples, 1, kMaxSamples,
              {"--samples", "Samples per pixel (each on its own wavelength band)"}),
        count("max_depth", &RenderSettings::maxDepth, 1, kMaxDepth,
              {"--max-depth", "Specular bounces followed from the camera"}),
        count("map_photons", &RenderSettings::mapPhotons, 1000, kMaxPhotons,
              {"--map-photons", "Photons traced for the caustic map and the angular plot"}),
        object("camera", &RenderSettings::camera, cameraSchema()),
    });
    return schema;
}

RenderSettings RenderSettings::fromJson(const nlohmann::json& j) {
    return renderSettingsSchema().read(j, "render");
}

nlohmann::json toJson(const RenderSettings& s) {
    return renderSettingsSchema().write(s);
}

}  // namespace facetlight
