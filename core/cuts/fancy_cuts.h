#pragma once
// Fancy brilliants: the round brilliant's tiers laid on another girdle outline. Every plane keeps the slope
// and azimuth it has on the round; its distance from the centre is scaled by how far the outline reaches in
// its direction (the outline's support function), so the stone stays an exact convex intersection.
#include <vector>

#include "cuts/round_brilliant.h"
#include "geometry/geometry.h"
#include "geometry/polygon_mesh.h"

namespace facetlight {

enum class FancyOutline { Oval, Pear, Marquise, Heart, Cushion, Princess, Radiant };

struct FancyBrilliantParams {
    FancyOutline outline = FancyOutline::Oval;
    RoundBrilliantParams tiers;  // proportions of the round whose planes are laid on the outline
    double ratio = 1.4;          // length / width
    double cornerPct = 25;       // cushion: corner radius, radiant: corner cut; % of the width
};

// The girdle outline with width 1 across y, long axis along x, centred on its bounding box, as a dense
// convex point set (its hull is the outline). The heart is convex: its cleft is filled in.
std::vector<Vec3> fancyOutline(const FancyBrilliantParams& params);

PolygonMesh makeFancyBrilliant(const FancyBrilliantParams& params);

}  // namespace facetlight
