#pragma once
// The inputs of a render (settings apart from the algorithm, as in Tungsten). fromJson() is strict: the
// service feeds it untrusted job JSON.
#include <cstdint>

#include <nlohmann/json.hpp>

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

    void validate() const;  // throws Error naming the field
    static RenderSettings fromJson(const nlohmann::json& j);
};

constexpr int kMinImageSide = 16;
constexpr int kMaxImageSide = 4096;
constexpr int kMaxSamples = 256;
constexpr int kMaxDepth = 64;
constexpr double kMinCameraDistance = 1;
constexpr double kMaxCameraDistance = 1000;
constexpr double kMaxFovDeg = 120;

nlohmann::json toJson(const RenderSettings& s);

}  // namespace facetlight
