#pragma once
// Rotations of vectors, for turning stones and views.
#include "geometry/geometry.h"

namespace facetlight {

// v turned about the unit axis k by the angle whose cosine and sine are given (Rodrigues' rotation formula).
inline Vec3 rotateAbout(const Vec3& v, const Vec3& k, double cosA, double sinA) {
    return v * cosA + cross(k, v) * sinA + k * (dot(k, v) * (1 - cosA));
}

}  // namespace facetlight
