#pragma once
// The round brilliant built from the proportions the trade grades: every facet a plane (azimuth, slope,
// offset), the stone their intersection. Conventions in docs/optics.md, "Round brilliant".
#include <vector>

#include "geometry/halfspace.h"
#include "geometry/polygon_mesh.h"
#include "util/name_table.h"

namespace facetlight {

// Where the upper and lower girdle halves lie. Trade: the stone DiamCalc, GIA reports and HCA-style tools
// assume, each half through its main's (bezel's) girdle point, the 22.5-deg girdle point where it meets its
// neighbour, and the mains' (bezels') meeting point at the lower-half (star) length. Faceter: a GemCad-style
// diagram, each half one index of a 96 gear (3.75 deg) off its main: a different stone.
enum class HalvesLayout { Trade, Faceter };
// The layouts' names, as the cut library's `halves` takes them.
inline constexpr NameTable<HalvesLayout, 2> kHalvesLayoutNames{
    {{{HalvesLayout::Trade, "trade"}, {HalvesLayout::Faceter, "faceter"}}}};

struct RoundBrilliantParams {
    double tablePct = 57;            // corner to corner, % of the girdle diameter
    double crownAngleDeg = 34;       // bezel slope
    double pavilionAngleDeg = 40.7;  // pavilion main slope
    double girdlePct = 2.5;          // where the girdle is thinnest (the middle of each half); 0 = knife edge
    double starPct = 50;             // horizontal, from the table edge toward the girdle
    double lowerHalfPct = 80;        // horizontal, from the girdle toward the centre
    double culetPct = 0;             // flat to flat, % of the diameter; 0 = pointed
    int girdleFacets = 0;            // 0 = smooth girdle (64 flat sides); else a multiple of 16
    HalvesLayout halves = HalvesLayout::Trade;
};

// The facet planes of the stone with girdle diameter 1, girdle centred on z = 0. Throws Error naming the
// input when the proportions cannot make this stone.
std::vector<NamedPlane> roundBrilliantPlanes(const RoundBrilliantParams& params);

// The heights of the girdle's top and bottom rims at the bezels' and mains' girdle points: where the girdle is
// thickest with the trade's halves, which take it down to girdle % midway between those points.
struct GirdleRims {
    double upper, lower;  // z; lower is negative
};
GirdleRims girdleRims(const RoundBrilliantParams& params);

// The intersection of those planes; also checks that every designed facet survived it.
PolygonMesh makeRoundBrilliant(const RoundBrilliantParams& params);

// The girdle facet count a setting stands for (64 for the smooth girdle, none for a knife edge).
int girdleSideCount(const RoundBrilliantParams& params);

}  // namespace facetlight
