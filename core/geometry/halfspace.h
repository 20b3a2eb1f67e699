#pragma once
// The convex solid bounded by a set of planes, built in double precision by clipping a large box by each
// plane in turn. GemCad designs and the parametric cut library both describe stones this way.
#include <string>
#include <vector>

#include "geometry/geometry.h"
#include "geometry/polygon_mesh.h"

namespace facetlight {

struct NamedPlane {
    Plane plane;  // the solid is where plane.signedDistance(p) <= 0
    std::string name;
};

// The intersection of the half-spaces as polygons named after their planes. Planes that end up touching the
// solid in less than a polygon contribute nothing. Vertices closer than `weld` (at least a billionth of the
// planes' reach) are one vertex: a design whose planes meet at a point only to its printed precision gets
// one meet there, not a crowd of slivers. Throws Error when the intersection is empty or unbounded.
PolygonMesh intersectHalfSpaces(const std::vector<NamedPlane>& planes, double weld = 0);

}  // namespace facetlight
