#pragma once
// Writing GemCad .asc designs: a design read (and perhaps tweaked) by facetlight, or any convex stone, as the
// text GemCad and the faceting machines' tools read.
#include <string>
#include <vector>

#include "io/gemcad_design.h"
#include "stone/stone.h"

namespace facetlight {

// The design as .asc text: "GemCad 5.0", the gear, symmetry, index, headers, one "a" line per tier (angle,
// distance to 8 decimals, the indices with their names, "G" instructions; a culet as GemCad's manual writes
// it, angle 0 with a negative distance), footnotes. parseGemCadDesign() reads it back to the same design.
std::string writeGemCad(const GemCadDesign& design);

// A convex stone as a design on a `gear`-tooth gear: each facet a plane at its slope, azimuth (as an index,
// fractional where it falls between teeth) and distance from the stone's centre; facets whose names share a
// stem ("pavilion_main_3": "pavilion_main") and whose slope and distance agree make one tier. Throws Error for
// a stone that is not convex, which no set of planes describes.
// `tierOfFacet`, if given, receives each stone facet's tier.
GemCadDesign gemCadDesignOf(const Stone& stone, int gear = 96, std::vector<size_t>* tierOfFacet = nullptr);

}  // namespace facetlight
