#pragma once
// Writing stones as Wavefront OBJ: one `g <facet name>` group per facet, so the names survive a round trip
// through parseObj().
#include <string>

#include "geometry/polygon_mesh.h"
#include "stone/stone.h"

namespace facetlight {

// OBJ text with `header` as leading comment lines (may be empty). Coordinates are written with nine decimals.
std::string objText(const PolygonMesh& mesh, const std::string& header = {});
// The stone's facets as polygons (their outlines), in the stone's frame.
std::string objText(const Stone& stone, const std::string& header = {});

// Writes the text to `path`; throws Error with the path when the file cannot be written.
void writeTextFile(const std::string& path, const std::string& text);

}  // namespace facetlight
