#pragma once
// A GemCad design as its file states it: the index gear, the symmetry, the index of refraction, the header
// and footnote text, and tiers of facets. Every facet is a plane at the tier's slope angle and distance, at
// the azimuth its index gives; the stone is the intersection of the planes' half-spaces.
//
// Conventions (docs/optics.md, "GemCad designs"): the angle is the facet's slope from the girdle plane, 0 the
// table, 90 the girdle, negative (including "-0", a culet) on the pavilion; its outward normal is tilted
// |angle| from +z (from -z on the pavilion). Index i on a g-tooth gear with offset o has azimuth
// phi = 360 (i - o) / g, clockwise seen from above, from +y: index 0 points to +y, index g/4 to +x. A negative
// gear numbers its teeth the other way round; indices outside 0..|g| wrap around the gear.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/halfspace.h"
#include "geometry/polygon_mesh.h"

namespace facetlight {

struct GemCadFacet {
    double index = 0;
    std::string name;  // the name the file gives this facet ("n" after its index), or empty
};

struct GemCadTier {
    double angleDeg = 0;  // signed slope; std::signbit tells the pavilion, so "-0" is a culet
    double distance = 0;  // the plane's distance from the origin, in the design's units
    std::vector<GemCadFacet> facets;
    std::string name;          // the first facet name the tier gives, or "tier<k>" for the k-th tier
    std::string instructions;  // GemCad's "G" cutting instructions, verbatim
    bool pavilion() const { return std::signbit(angleDeg); }
};

struct GemCadDesign {
    int gear = 96;  // teeth, signed (see above)
    double gearOffset = 0;
    int symmetry = 1;
    bool mirror = false;
    std::optional<double> refractiveIndex;  // the file's "I" line
    std::vector<std::string> headers;       // "H" lines, the first usually the title
    std::vector<std::string> footnotes;     // "F" lines
    std::vector<GemCadTier> tiers;
    std::vector<std::string> warnings;      // remarks that are not errors, with their line numbers
    // Half the last printed digit of the distances (5e-7 for "0.668000"): meets are exact only to this.
    double distancePrecision = 0;
};

// Reads a GemCad .asc text. Throws Error naming the line on anything it cannot read.
GemCadDesign parseGemCadDesign(std::string_view text, const MeshLimits& limits = {});

// Reads a GemCad binary .gem project file into the same design (layout: docs/optics.md, "GemCad designs").
GemCadDesign parseGemCadBinary(std::string_view bytes, const MeshLimits& limits = {});

// The azimuth of an index on the design's gear, degrees clockwise from +y in [0, 360).
double gemCadAzimuthDeg(const GemCadDesign& design, double index);
// The outward unit normal of a facet at the tier's angle and the index's azimuth.
Vec3 gemCadNormal(double angleDeg, double azimuthDeg);

// The facet planes, named per tier and numbered across the file (P1_1 ... P1_8; a lone facet keeps its
// bare name, T).
std::vector<NamedPlane> gemCadPlanes(const GemCadDesign& design);

// Cuts the stone the design describes. Vertices closer than the file's printed precision allows are one
// meet. Facets that do not reach the surface are warnings; an open or empty solid is an Error.
PolygonMesh buildGemCadMesh(const GemCadDesign& design, const MeshLimits& limits = {});

}  // namespace facetlight
