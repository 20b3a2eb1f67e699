#pragma once
// A mesh's polygons as the stone's triangles: exactly repeated vertices welded into one, each polygon cut
// into triangles in its own plane.
#include <cstdint>
#include <vector>

#include "geometry/geometry.h"
#include "geometry/polygon_mesh.h"
#include "stone/stone.h"

namespace facetlight {

struct Triangulation {
    std::vector<Vec3> vertices;       // the mesh's, welded
    std::vector<Triangle> triangles;  // facet 0 each, until the facets are merged
    std::vector<uint32_t> source;     // each triangle's input polygon, for messages and facet names
};

// `scale`: the length of the mesh's extent, which the zero-area tolerance is a fraction of (squared). Throws
// Error naming the face that is degenerate (zero area) or self-intersecting.
Triangulation triangulate(const PolygonMesh& mesh, double scale);

}  // namespace facetlight
