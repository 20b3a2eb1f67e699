#pragma once
// What makes a mesh a stone: within the limits, finite, closed, manifold, one piece, consistently oriented,
// enclosing a volume and not passing through itself; and whether it is convex. The refusals are Errors
// naming the problem (and the faces or vertices, counted from 1 as in the file).
#include <cstdint>
#include <vector>

#include "geometry/polygon_mesh.h"
#include "stone/detail/edge_map.h"
#include "stone/stone.h"

namespace facetlight {

// Refuses a mesh beyond `limits`, with a coordinate not finite or too far out, a face of fewer than 3 or too
// many vertices or naming a vertex that is not there, or too small an extent. Returns the length of the
// extent: the scale the tolerances of the other steps are fractions of.
double checkMeshInput(const PolygonMesh& mesh, const MeshLimits& limits);

// Refuses the triangulated surface unless it is closed, manifold, one piece, consistently oriented,
// enclosing a volume and not passing through itself; turns it outward, with a warning, when all of it faces
// inward. `source`: each triangle's input polygon.
void checkClosedAndOrient(Stone& stone, const std::vector<uint32_t>& source, double scale);

// A closed connected surface that is convex across every edge is convex (Tietze), so it is enough to check
// each edge's far vertex against the facet plane on this side. `directed`: each directed edge's triangle.
bool isConvex(const Stone& stone, const detail::EdgeMap& directed, double scale);

}  // namespace facetlight
