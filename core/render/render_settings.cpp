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

const Schema<FirePictureSettings>& firePictureSettingsSchema() {
    static const Schema<FirePictureSettings> schema({
        count("wavelengths", &FirePictureSettings::wavelengths, 1, kMaxFireWavelengths,
              {"--fire-picture-wavelengths",
               "Fire picture: wavelengths per pixel, stratified over 380-730 nm"}),
        number("light_tilt_deg", &FirePictureSettings::lightTiltDeg, {.lo = 0, .hi = 89},
               {"--fire-picture-light-tilt", "Fire picture: the light's angle from the vertical", "degrees"}),
        number(
            "light_radius_deg", &FirePictureSettings::lightRadiusDeg, {.lo = 0.05, .hi = 20},
            {"--fire-picture-light-radius", "Fire picture: angular radius of the light's disc", "degrees"}),
        number("ambient", &FirePictureSettings::ambient, {.lo = 0, .hi = 1},
               {"--fire-picture-ambient", "Fire picture: the dim room's light, a share of the studio's"}),
    });
    return schema;
}

FirePictureSettings FirePictureSettings::fromJson(const nlohmann::json& j) {
    return firePictureSettingsSchema().read(j, "fire_picture");
}

nlohmann::json toJson(const FirePictureSettings& s) {
    return firePictureSettingsSchema().write(s);
}

}  // namespace facetlight
