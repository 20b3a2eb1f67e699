#pragma once
// Newell's normal of a polygon: robust where three of its vertices are collinear.
#include <cstdint>
#include <vector>

#include "geometry/geometry.h"

namespace facetlight::detail {

// The normal of the vertex loop `loop` into `points`; its length is twice the polygon's area.
inline Vec3 newellNormal(const std::vector<Vec3>& points, const std::vector<uint32_t>& loop) {
    Vec3 n;
    for (size_t i = 0; i < loop.size(); ++i) {
        const Vec3& a = points[loop[i]];
        const Vec3& b = points[loop[(i + 1) % loop.size()]];
        n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    return n;
}

}  // namespace facetlight::detail
