#pragma once
// Shared steps of the parametric cuts: a facet plane from the angles a cutter sets, and the intersection of
// a design's planes with the check that every designed facet survived it.
#include <string>
#include <vector>

#include "geometry/halfspace.h"
#include "geometry/polygon_mesh.h"

namespace facetlight {

// A crown (up) or pavilion (!up) facet plane with the given azimuth and slope (degrees) through a point.
NamedPlane facetPlane(std::string name, double azimuthDeg, double slopeDeg, bool up, const Vec3& through);

Vec3 polar(double radius, double azimuthDeg, double z);

// intersectHalfSpaces(), then an Error naming the first facet (girdle facets aside) that the other planes
// cut away entirely, with `hint` saying which inputs to revisit.
PolygonMesh intersectDesign(const std::vector<NamedPlane>& planes, const std::string& hint);

// "%g" of a value, for messages.
std::string formatNumber(double v);

}  // namespace facetlight
