#include "stone/standard_frame.h"

#include <cmath>
#include <functional>
#include <string>

#include "geometry/rotation.h"
#include "stone/detail/newell.h"
#include "stone/girdle.h"
#include "util/error.h"

namespace facetlight {

namespace {

void transform(Stone& stone, const std::function<Vec3(const Vec3&)>& move) {
    for (auto& v : stone.vertices) v = move(v);
}

}  // namespace

void moveToStandardFrame(Stone& stone, double scale, bool reorient) {
    auto facetNormal = [&](const Facet& f) {
        return normalize(detail::newellNormal(stone.vertices, f.outline));
    };
    bool horizontal = false;
    const Facet* largest = nullptr;
    double largestArea = -1;
    for (const auto& f : stone.facets) {
        const Vec3 n = facetNormal(f);
        horizontal |= std::fabs(n.z) > 1 - 1e-9;
        const double area = 0.5 * length(detail::newellNormal(stone.vertices, f.outline));
        if (area > largestArea) largestArea = area, largest = &f;
    }
    if (!largest || !(largestArea > 0)) throw Error("the mesh has no facet of positive, finite area");
    StoneFrame& frame = stone.frame;
    frame = {};
    if (reorient && !horizontal) {
        const Vec3 from = facetNormal(*largest);
        const Vec3 axis = cross(from, Vec3{0, 0, 1});
        const double s = length(axis), c = from.z;
        frame.fileOrientation = false;
        // Named as finishFacets() will name it when the file gave it no name.
        frame.tableFacet = largest->name.empty() ? "facet_" + std::to_string(largest->id + 1) : largest->name;
        frame.turnedDeg = degrees(std::atan2(s, c));
        if (s > 1e-12) {
            const Vec3 k = axis / s;
            transform(stone, [&](const Vec3& v) { return rotateAbout(v, k, c, s); });
        } else if (c < 0) {
            transform(stone, [](const Vec3& v) { return Vec3{v.x, -v.y, -v.z}; });
        }
    }
    Bounds3 b;
    for (const auto& v : stone.vertices) b.extend(v);
    if (reorient && b.extent().y > b.extent().x * 1.001) {  // the long axis along x
        transform(stone, [](const Vec3& v) { return Vec3{v.y, -v.x, v.z}; });
        frame.fileOrientation = false;
        frame.longAxisTurned = true;
    }
    b = {};
    for (const auto& v : stone.vertices) b.extend(v);
    const GirdleBand band = girdleBand(stone, scale);
    frame.shift = {b.center().x, b.center().y, 0.5 * (band.top + band.bottom)};
    transform(stone, [&](const Vec3& v) { return v - frame.shift; });
}

}  // namespace facetlight
