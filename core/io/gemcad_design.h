#pragma once
// Reading and cutting GemCad designs (the design itself: geometry/gemcad_design.h).
#include <string_view>
#include <vector>

#include "geometry/gemcad_design.h"
#include "geometry/halfspace.h"
#include "geometry/polygon_mesh.h"

namespace facetlight {

// Reads a GemCad .asc text. Throws Error naming the line on anything it cannot read.
GemCadDesign parseGemCadDesign(std::string_view text, const MeshLimits& limits = {});

// Reads a GemCad binary .gem project file into the same design (layout: docs/optics.md, "GemCad binary .gem").
GemCadDesign parseGemCadBinary(std::string_view bytes, const MeshLimits& limits = {});

// The azimuth of an index on the design's gear, degrees clockwise from +y in [0, 360).
double gemCadAzimuthDeg(const GemCadDesign& design, double index);
// The outward unit normal of a facet at the tier's angle and the index's azimuth.
Vec3 gemCadNormal(double angleDeg, double azimuthDeg);

// The facet planes, named per tier and numbered across the file (P1_1 ... P1_8; a lone facet keeps its
// bare name, T).
std::vector<NamedPlane> gemCadPlanes(const GemCadDesign& design);
// The tier name a facet name was numbered from ("P1_3": "P1"; "T": "T"): the stem before a trailing "_<n>".
std::string facetNameStem(const std::string& name);

// Cuts the stone the design describes. Vertices closer than the file's printed precision allows are one
// meet. Facets that do not reach the surface are warnings; an open or empty solid is an Error.
PolygonMesh buildGemCadMesh(const GemCadDesign& design, const MeshLimits& limits = {});

}  // namespace facetlight
