#pragma once
// Any stone file as a shape a sweep or a search can vary (docs/gemcad.md). A GemCad design's sloped tiers are
// its parameters, "tier:<name>" (the tier's slope in degrees, on its own side of the girdle), each re-cut the
// way a cutter tweaks a tier: every facet of the tier turns to the new slope about the meet it keeps, its
// point farthest from the stone's axis (for a tier that reaches the girdle, where it meets the girdle), and
// every other tier stays where it was. A mesh file has no parameters: a sweep of it varies trace settings.
#include <memory>
#include <string>

#include "cuts/cut_library.h"
#include "io/gemcad_design.h"
#include "io/mesh_io.h"

namespace facetlight {

// The design with the tiers' slopes `values` gives, each re-cut through the meet it keeps on `built`, the
// design's own stone (buildGemCadMesh). Values name tiers by tierParameter(); others stay as designed.
// Throws Error when a re-cut tier would not pass the stone's centre on its own side.
GemCadDesign retier(const GemCadDesign& design, const PolygonMesh& built, const CutValues& values);

// The shape of a file: named after its stem; `design` set for a GemCad design (parameters: its tiers),
// null for a mesh. Throws Error as loadStone() does.
struct FileShape {
    CutShape shape;
    std::shared_ptr<const GemCadDesign> design;
    // The design a point's values describe (retier), for writing it back as .asc; needs `design`.
    GemCadDesign designAt(const CutValues& values) const;
    std::shared_ptr<const PolygonMesh> built;  // the design's (or the mesh's) own polygons
};
std::shared_ptr<const FileShape> fileShape(const std::string& path, const MeshLimits& limits = {});

}  // namespace facetlight
