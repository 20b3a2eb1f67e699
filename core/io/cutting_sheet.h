#pragma once
// A GemCad-style cutting sheet of a stone (docs/gemcad.md, "Cutting sheet"): each tier's name, angle, indices,
// distance and facet count as designed, with what the cut stone shows: the tier's slope measured back from its
// facets, how many of them reach the surface, and the tiers it meets.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "stone/stone.h"

namespace facetlight {

struct SheetTier {
    std::string name;
    double angleDeg = 0;  // as designed, signed: negative on the pavilion
    double distance = 0;
    std::vector<double> indices;
    std::string instructions;
    size_t facets = 0;     // designed
    size_t facetsCut = 0;  // of those, on the stone's surface
    std::optional<double> measuredAngleDeg;  // the mean slope of its facets on the stone, signed
    std::vector<std::string> meets;          // the tiers that share an edge with it
};

struct CuttingSheet {
    std::string source;  // "GemCad design", or "measured from the mesh" (facets grouped into tiers)
    int gear = 96;
    double gearOffset = 0;
    int symmetry = 1;
    bool mirror = false;
    std::optional<double> refractiveIndex;
    std::vector<std::string> headers, footnotes;
    std::vector<SheetTier> tiers;
};

// The sheet of the stone's GemCad design; for a convex mesh, of its facets grouped into tiers on a 96 gear
// (gemCadDesignOf); for a mesh that is not convex, none.
std::optional<CuttingSheet> cuttingSheet(const Stone& stone);

nlohmann::json toJson(const CuttingSheet& sheet);
// An index as a faceter reads it: on the gear's own range, 1 to the tooth count (0 and -96 are 96), two digits
// at least ("03").
std::string gearIndexText(double index, int gear);
// The sheet as a faceter reads it: one line per tier, angles positive with the side named.
std::string cuttingSheetText(const CuttingSheet& sheet);

}  // namespace facetlight
