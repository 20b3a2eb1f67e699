#pragma once
// The standard frame a stone is measured and traced in: girdle plane z = 0, table up, long axis along x,
// centred on the z axis.
#include "stone/stone.h"

namespace facetlight {

// Moves the stone's vertices into the standard frame and records what it did in stone.frame. With `reorient`
// (meshes without --keep-frame): table up keeps the file's z axis when some facet faces straight up or down
// (the usual case for designs), else turns the largest facet, taken to be the table, to face +z; the long
// axis is turned onto x. Without it (GemCad designs, --keep-frame) the stone is only centred. Reads the
// facets' outlines, before their normals are set; `scale`: the length of the mesh's extent, which the
// tolerances are fractions of. Throws Error when no facet has a positive area.
void moveToStandardFrame(Stone& stone, double scale, bool reorient);

}  // namespace facetlight
