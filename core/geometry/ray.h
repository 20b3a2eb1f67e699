#pragma once
// Single-precision vectors for the photon loop: the intersectors and the tracer work in float, which halves
// the width of the SIMD plane tests and matches Embree's own precision.
#include <cmath>
#include <cstdint>

#include "geometry/geometry.h"

namespace facetlight {

struct Vec3f {
    float x = 0, y = 0, z = 0;
    constexpr Vec3f() = default;
    constexpr Vec3f(float x_, float y_, float z_) : x(x_), y(y_), z(z_) {}
    explicit constexpr Vec3f(const Vec3& v) : x(float(v.x)), y(float(v.y)), z(float(v.z)) {}
    constexpr Vec3f operator+(const Vec3f& b) const { return {x + b.x, y + b.y, z + b.z}; }
    constexpr Vec3f operator-(const Vec3f& b) const { return {x - b.x, y - b.y, z - b.z}; }
    constexpr Vec3f operator*(float s) const { return {x * s, y * s, z * s}; }
    constexpr Vec3f operator-() const { return {-x, -y, -z}; }
};

constexpr float dot(const Vec3f& a, const Vec3f& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
constexpr Vec3 toVec3(const Vec3f& v) {
    return {v.x, v.y, v.z};
}
constexpr Vec3f cross(const Vec3f& a, const Vec3f& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Vec3f normalize(const Vec3f& v) {
    return v * (1.0f / std::sqrt(dot(v, v)));
}

// Where a ray meets the stone's surface: the distance along the ray and the facet crossed.
struct SurfaceHit {
    float t = 0;
    uint32_t facet = 0;
};

}  // namespace facetlight
