#pragma once
// A cut stone: a closed, outward-oriented triangle mesh grouped into planar facets, put in the standard frame
// (girdle plane z = 0, table up, centred on the z axis) with its regions and trade proportions measured.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/geometry.h"
#include "geometry/polygon_mesh.h"

namespace facetlight {

enum class Region : uint8_t { Table, Crown, Girdle, Pavilion };
constexpr int kRegionCount = 4;
std::string_view regionName(Region r);

struct Triangle {
    std::array<uint32_t, 3> v;  // counter-clockwise seen from outside
    uint32_t facet;             // index into Stone::facets
};

struct Facet {
    uint32_t id = 0;       // index in Stone::facets
    std::string name;      // from the file or design; "facet_<id>" when the file gave none
    Region region = Region::Crown;
    Vec3 normal;           // outward unit normal (Newell's method over the outline)
    double offset = 0;     // plane: dot(normal, p) == offset
    double area = 0;
    Vec3 centroid;
    std::vector<uint32_t> triangles;  // indices into Stone::triangles
    std::vector<uint32_t> outline;    // vertex loop, counter-clockwise seen from outside
    Plane plane() const { return {normal, offset}; }
};

// Trade proportions, as percentages of the girdle diameter (of the width for fancy shapes) and degrees;
// empty where a figure does not apply to the cut.
struct Proportions {
    double length = 0;  // the girdle outline's longer horizontal extent (along x or y)
    double width = 0;   // its shorter one
    double diameter = 0;  // reference size for the percentages: the width (the diameter for a round)
    // Crown height and pavilion depth run from the table and the culet to the girdle's rims where the mains
    // meet it; girdlePct is the girdle where thinnest, girdleThickestPct where thickest.
    std::optional<double> tablePct, crownHeightPct, pavilionDepthPct, girdlePct, girdleThickestPct, totalDepthPct;
    std::optional<double> crownAngleDeg, pavilionAngleDeg;
    // A round brilliant's minor tiers, as a GIA report lists them: the mean slopes of the stars (crown facets
    // at the table that miss the girdle), upper halves (at the girdle, not the table) and lower halves (at
    // the girdle, not the culet); star % from the table edge to the girdle and lower-half % from the girdle
    // to the centre, both horizontal, at the stars' tips and the lower halves' innermost points.
    std::optional<double> starAngleDeg, upperHalfAngleDeg, lowerHalfAngleDeg, starPct, lowerHalfPct;
};

struct StoneOptions {
    MeshLimits limits;
    // Move the stone into the standard frame. Off only for tests of the raw geometry.
    bool standardFrame = true;
    // Keep the file's orientation, only centring the stone (--keep-frame); GemCad designs always keep theirs.
    bool keepFrame = false;
};

// What was done to the file's geometry to put the stone in the standard frame, so a user can tell.
struct StoneFrame {
    bool fileOrientation = true;  // the file's up and azimuths kept
    std::string tableFacet;       // when not: the facet turned to face up, taken to be the table
    double turnedDeg = 0;         // the angle it was turned through
    bool longAxisTurned = false;  // turned a quarter turn about z to lay the long axis along x
    Vec3 shift;                   // subtracted from every vertex: centred on z, girdle at z = 0
};

class Stone {
public:
    // Validates `mesh` and interprets it: triangulates polygons, merges coplanar edge-connected triangles into
    // facets, fixes a wholly flipped orientation (with a warning), refuses open, inconsistent, degenerate or
    // non-finite meshes with an Error naming the problem, then classifies regions and measures proportions.
    static Stone build(const PolygonMesh& mesh, std::string name, const StoneOptions& options = {});

    std::string name;
    std::vector<Vec3> vertices;
    std::vector<Triangle> triangles;
    std::vector<Facet> facets;
    bool convex = false;
    Bounds3 bounds;
    Proportions proportions;
    StoneFrame frame;
    std::shared_ptr<const GemCadDesign> design;  // the GemCad design it was cut from, if any
    std::vector<std::string> warnings;

    int facetCount(Region r) const;
    double volume() const;
};

}  // namespace facetlight
