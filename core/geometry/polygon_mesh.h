#pragma once
// What a loader reads from a file, before it is understood as a stone: vertices and polygons, each polygon
// with the group name the file gave it (empty when none). Stone::build() validates and interprets it.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "geometry/gemcad_design.h"
#include "geometry/geometry.h"

namespace facetlight {

struct PolygonMesh {
    struct Polygon {
        std::vector<uint32_t> vertices;  // indices into `vertices`, counter-clockwise seen from outside
        std::string name;                // facet name from the file (OBJ g/o/usemtl, GemCad tier), or empty
    };
    std::vector<Vec3> vertices;
    std::vector<Polygon> polygons;
    std::vector<std::string> warnings;   // loader remarks that are not errors (e.g. "fixed orientation")
    // The GemCad design the polygons were cut from, if any. Its frame is the stone's (up is the file's up,
    // index 0 its +y): a design is never re-oriented.
    std::shared_ptr<const GemCadDesign> design;
};

// Caps that protect the process from hostile or absurd input; loaders refuse meshes beyond them.
struct MeshLimits {
    size_t maxVertices = 2'000'000;
    size_t maxPolygons = 2'000'000;
    // A file read from disk (the service caps uploads itself): room for 2 M triangles of binary STL.
    size_t maxFileBytes = size_t(256) << 20;
};

// Coordinates (and plane distances) beyond this are refused: no stone comes near it in any length unit, and
// products of three coordinates (volumes) stay far inside the range of a double. Huge ones made every
// facet's area NaN.
constexpr double kMaxMeshCoordinate = 1e9;
// The smallest extent a stone may have; below it areas (squares) and volumes (cubes) lose precision.
constexpr double kMinMeshExtent = 1e-9;

}  // namespace facetlight
