#pragma once
// A GemCad design as its file states it: the index gear, the symmetry, the index of refraction, the header
// and footnote text, and tiers of facets. Every facet is a plane at the tier's slope angle and distance, at
// the azimuth its index gives; the stone is the intersection of the planes' half-spaces. Plain data, so that
// a mesh and the stone built from it can carry the design they came from; io/gemcad_design.h reads it, cuts
// it and writes it.
//
// Conventions (docs/optics.md, "GemCad designs"): the angle is the facet's slope from the girdle plane, 0 the
// table, 90 the girdle, negative (including "-0", a culet) on the pavilion; its outward normal is tilted
// |angle| from +z (from -z on the pavilion). Index i on a g-tooth gear with offset o has azimuth
// phi = 360 (i - o) / g, clockwise seen from above, from +y: index 0 points to +y, index g/4 to +x. A negative
// gear numbers its teeth the other way round; indices outside 0..|g| wrap around the gear.
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

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
    size_t line = 0;           // where the file states the tier, for messages; 0 when not read from text
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

// A sloped tier (0 < |angle| < 90) can be tweaked; the table, a culet and the girdle cannot.
inline bool tweakableTier(const GemCadTier& tier) {
    const double slope = std::fabs(tier.angleDeg);
    return slope > 0 && slope < 90;
}

// The name of a tier as a sweep's parameter: "tier:" and its name ("tier:P1"); a name that an earlier tier
// has too gets the tier's position in the file ("tier:P1@4").
inline std::string tierParameter(const GemCadDesign& design, size_t tier) {
    const std::string& name = design.tiers.at(tier).name;
    for (size_t t = 0; t < tier; ++t)
        if (design.tiers[t].name == name) return "tier:" + name + "@" + std::to_string(tier + 1);
    return "tier:" + name;
}

}  // namespace facetlight
