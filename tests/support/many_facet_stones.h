#pragma once
// Designs of many facets and no round girdle for the exit search to skip (issue 32), built from planes: the
// real-design corpus (tests/data/gemcad) has no briolette and no design of 200 facets or more. Used by the
// intersector tests and bench_trace.
#include <cmath>
#include <string>
#include <vector>

#include "cuts/facet_design.h"
#include "geometry/halfspace.h"
#include "stone/stone.h"

namespace facetlight::test {

// Tiers of facets tangent to a convex egg: the upper half of the ellipsoid with semi-axes (rx, ry, top) on
// the lower half of the one with (rx, ry, bottom). Tier k's normals lie at (k + 1/2) / tiers of the way from
// up to down, `perTier` of them, every other tier turned half a step (the checkerboard's bricks). Each plane
// touches the egg at one point, so every facet is kept.
inline Stone facetedEgg(const std::string& name, int tiers, int perTier, double rx, double ry, double top,
                        double bottom) {
    std::vector<NamedPlane> planes;
    for (int k = 0; k < tiers; ++k) {
        const double polar = kPi * (k + 0.5) / tiers;
        for (int j = 0; j < perTier; ++j) {
            const double azimuth = 2 * kPi * (j + 0.5 * (k % 2)) / perTier;
            const Vec3 n{std::sin(polar) * std::cos(azimuth), std::sin(polar) * std::sin(azimuth),
                         std::cos(polar)};
            const double c = n.z > 0 ? top : bottom;
            const double reach = std::sqrt(rx * rx * n.x * n.x + ry * ry * n.y * n.y + c * c * n.z * n.z);
            planes.push_back({{n, reach}, "tier_" + std::to_string(k + 1) + "_" + std::to_string(j + 1)});
        }
    }
    return Stone::build(intersectHalfSpaces(planes), name);
}

// A drop-shaped briolette of 304 facets (19 tiers of 16), long and pointed above, rounded below.
inline Stone briolette() {
    return facetedEgg("briolette_304", 19, 16, 0.5, 0.5, 1.3, 0.6);
}

// An oval checkerboard of 240 facets (10 tiers of 24): a low crown of bricks over a deep pavilion.
inline Stone checkerboard() {
    return facetedEgg("checkerboard_oval_240", 10, 24, 0.6, 0.45, 0.3, 0.55);
}

// A step cut of 217 facets: an octagon (a 1.4 : 1 rectangle with corners cut at 15 % of the width), table,
// 8 girdle flats, 12 crown steps from 45 deg flattening by 3 deg and 14 pavilion steps from 60 deg
// flattening by 3.3 deg, each ring an inward offset of the outline (the pavilion ends in a ridge).
inline Stone stepCut217() {
    const double ratio = 1.4, corner = 0.15, girdle = 0.01;
    auto edge = [&](int side) {
        if (side % 4 == 0) return ratio / 2;
        if (side % 4 == 2) return 0.5;
        return (ratio / 2 + 0.5 - corner) / std::sqrt(2.0);
    };
    std::vector<NamedPlane> planes;
    constexpr int kCrown = 12, kPavilion = 14;
    const double crownWidth = 0.5 * (1 - 0.55) / kCrown;
    double z = girdle;
    for (int i = 0; i < kCrown; ++i) {
        const double slope = 45 - 3 * i;
        for (int side = 0; side < 8; ++side)
            planes.push_back(facetPlane("crown_" + std::to_string(i + 1) + "_" + std::to_string(side + 1),
                                        45.0 * side, slope, true,
                                        polar(edge(side) - i * crownWidth, 45.0 * side, z)));
        z += crownWidth * std::tan(radians(slope));
    }
    planes.push_back({{{0, 0, 1}, z}, "table"});
    for (int side = 0; side < 8; ++side) {
        const double az = radians(45.0 * side);
        planes.push_back(
            {{{std::cos(az), std::sin(az), 0}, edge(side)}, "girdle_" + std::to_string(side + 1)});
    }
    const double pavilionWidth = 0.24 / kPavilion;  // the corners last to an offset of 0.256
    z = -girdle;
    for (int i = 0; i < kPavilion; ++i) {
        const double slope = 60 - 3.3 * i;
        for (int side = 0; side < 8; ++side)
            planes.push_back(facetPlane("pavilion_" + std::to_string(i + 1) + "_" + std::to_string(side + 1),
                                        45.0 * side, slope, false,
                                        polar(edge(side) - i * pavilionWidth, 45.0 * side, z)));
        z -= pavilionWidth * std::tan(radians(slope));
    }
    return Stone::build(intersectHalfSpaces(planes), "step_cut_217");
}

}  // namespace facetlight::test
