#include "render/camera.h"

#include <cmath>

namespace facetlight {

Camera::Camera(const CameraSettings& s, const Vec3& target, double scale, int width, int height) {
    // The face-up frame (looking down -z, right +x, up +y) rotated by 90 - elevation about x, then by the
    // azimuth about z: continuous at every elevation, so no special case at the pole.
    const double a = radians(90 - s.elevationDeg), az = radians(s.azimuthDeg);
    const double ca = std::cos(a), sa = std::sin(a), cz = std::cos(az), sz = std::sin(az);
    auto turn = [&](const Vec3& v) { return Vec3{v.x * cz - v.y * sz, v.x * sz + v.y * cz, v.z}; };
    forward_ = turn({0, sa, -ca});
    up_ = turn({0, ca, sa});
    right_ = turn({1, 0, 0});
    position_ = target - forward_ * (s.distance * scale);
    halfHeight_ = std::tan(radians(s.fovDeg) / 2);
    invHeight_ = 1.0 / height;
    halfWidthPixels_ = 0.5 * width;
    halfHeightPixels_ = 0.5 * height;
}

Vec3 Camera::direction(double px, double py) const {
    const double u = (px - halfWidthPixels_) * 2 * invHeight_ * halfHeight_;
    const double v = (halfHeightPixels_ - py) * 2 * invHeight_ * halfHeight_;
    return normalize(forward_ + right_ * u + up_ * v);
}

}  // namespace facetlight
