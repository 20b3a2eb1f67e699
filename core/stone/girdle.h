#pragma once
// The girdle of a stone in the standard frame's orientation (table up): which facets belong to it, and its
// height where thinnest and thickest. The orientation centres the stone on it, the proportions measure it.
#include <cmath>

#include "geometry/geometry.h"
#include "stone/stone.h"

namespace facetlight {

// A girdle facet stands within ~1.1 deg of vertical.
inline bool isGirdleNormal(const Vec3& n) {
    return std::fabs(n.z) < 0.02;
}

struct GirdleBand {
    double top = 0, bottom = 0;
};

// The girdle's top and bottom at its thinnest point; for a knife-edge girdle, the height of the widest
// horizontal section. Reads the facets' outlines only, so it serves before their normals are set. `scale`:
// the length of the mesh's extent, which the tolerances are fractions of.
GirdleBand girdleBand(const Stone& stone, double scale);

// The girdle's height where it is thickest; 0 for a knife edge.
double girdleThickest(const Stone& stone, double scale);

}  // namespace facetlight
