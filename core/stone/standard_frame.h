#pragma once
// The standard frame a stone is measured and traced in: girdle plane z = 0, table up, long axis along x,
// centred on the z axis.
#include "stone/stone.h"

namespace facetlight {

// Moves the stone's vertices into the standard frame. Table up: keeps the file's z axis when some facet
// faces straight up or down (the usual case for designs), else turns the largest facet, taken to be the
// table, to face +z. Reads the facets' outlines, before their normals are set; `scale`: the length of the
// mesh's extent, which the tolerances are fractions of. Throws Error when no facet has a positive area.
void moveToStandardFrame(Stone& stone, double scale);

}  // namespace facetlight
