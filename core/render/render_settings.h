#pragma once
// The inputs of a render (settings apart from the algorithm, as in Tungsten), each described once in
// renderSettingsSchema(): JSON, checks, CLI flags and the API schema follow from it.
#include <cstdint>

#include <nlohmann/json.hpp>

#include "settings/settings_schema.h"

namespace facetlight {

struct CameraSettings {
    double elevationDeg = 90;  // 90: face-up, looking straight down on the table
    double azimuthDeg = 0;
    double distance = 4;  // in girdle diameters from the stone's centre
    double fovDeg = 20;   // vertical field of view
};

struct RenderSettings {
    int width = 400;
    int height = 400;
    int samples = 4;                // samples per pixel (antialiasing, and wavelengths with dispersion)
    int maxDepth = 12;              // specular bounces followed from the camera
    uint64_t mapPhotons = 200'000;  // photons stored for the caustic and global maps
    CameraSettings camera;

    // Missing keys keep their defaults; throws Error naming the field ("render.width").
    static RenderSettings fromJson(const nlohmann::json& j);
};

// The fire picture (render/fire_picture.h): the stone through the render's camera under one small bright
// light in a dim room, in spectral colour. Its job key is "fire_picture", apart from the fire measurement's.
struct FirePictureSettings {
    int wavelengths = 24;       // per pixel, one in each of as many equal strata of 380-730 nm
    double lightTiltDeg = 20;   // the light's angle from the vertical, leaning toward -y (the viewer's side)
    double lightRadiusDeg = 4;  // angular radius of the light's disc: a 14 cm lamp 1 m away
    double ambient = 0.02;      // the dim room: the studio environment's light times this

    // Missing keys keep their defaults; throws Error naming the field ("fire_picture.wavelengths").
    static FirePictureSettings fromJson(const nlohmann::json& j);
};

constexpr int kMinImageSide = 16;
constexpr int kMaxImageSide = 4096;
constexpr int kMaxSamples = 256;
constexpr int kMaxDepth = 64;

// Its paths start with "render.", where a job holds it.
const settings::Schema<RenderSettings>& renderSettingsSchema();
nlohmann::json toJson(const RenderSettings& s);

constexpr int kMaxFireWavelengths = 256;
// Its paths start with "fire_picture.", where a job holds it.
const settings::Schema<FirePictureSettings>& firePictureSettingsSchema();
nlohmann::json toJson(const FirePictureSettings& s);

}  // namespace facetlight
