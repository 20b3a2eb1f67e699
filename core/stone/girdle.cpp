#include "stone/girdle.h"

#include <algorithm>
#include <cmath>

#include "stone/detail/newell.h"

namespace facetlight {

namespace {

// The girdle's vertical sections: above or below each corner of each girdle facet, that facet's bottom and
// top. Each facet is a convex polygon in a vertical plane, so its height is piecewise linear along it and
// the girdle is thinnest and thickest at such corners.
template <class F>
void forEachGirdleSection(const Stone& stone, double scale, F&& section) {
    for (const auto& f : stone.facets) {
        const Vec3 n = normalize(detail::newellNormal(stone.vertices, f.outline));
        if (!isGirdleNormal(n)) continue;
        const Vec3 along = normalize(cross(n, Vec3{0, 0, 1}));
        const double flat = 1e-9 * scale;
        for (uint32_t at : f.outline) {
            const double u = dot(stone.vertices[at], along);
            double lo = INFINITY, hi = -INFINITY;
            for (size_t i = 0; i < f.outline.size(); ++i) {
                const Vec3& a = stone.vertices[f.outline[i]];
                const Vec3& b = stone.vertices[f.outline[(i + 1) % f.outline.size()]];
                const double ua = dot(a, along), ub = dot(b, along);
                if (std::fabs(ub - ua) <= flat) {  // an upright edge: both its ends, if it stands here
                    if (std::fabs(u - ua) <= flat)
                        lo = std::min({lo, a.z, b.z}), hi = std::max({hi, a.z, b.z});
                } else if ((u - ua) * (u - ub) <= 0) {
                    const double z = a.z + (b.z - a.z) * (u - ua) / (ub - ua);
                    lo = std::min(lo, z), hi = std::max(hi, z);
                }
            }
            if (lo <= hi) section(lo, hi);
        }
    }
}

}  // namespace

GirdleBand girdleBand(const Stone& stone, double scale) {
    GirdleBand thinnest;
    double least = INFINITY;
    forEachGirdleSection(stone, scale, [&](double lo, double hi) {
        if (hi - lo < least) least = hi - lo, thinnest = {hi, lo};
    });
    if (least < INFINITY) return thinnest;
    double bestR = -1, z = 0;
    Bounds3 b;
    for (const auto& v : stone.vertices) b.extend(v);
    const Vec3 c = b.center();
    for (const auto& v : stone.vertices) {
        const double r = std::hypot(v.x - c.x, v.y - c.y);
        if (r > bestR + 1e-9 * scale) bestR = r, z = v.z;
    }
    return {z, z};
}

double girdleThickest(const Stone& stone, double scale) {
    double most = 0;
    forEachGirdleSection(stone, scale, [&](double lo, double hi) { most = std::max(most, hi - lo); });
    return most;
}

}  // namespace facetlight
