#pragma once
// The facet diagram: the crown and table seen from above (left) and the pavilion seen from below (right),
// each facet filled by its share of the light leaving the stone, with outlines, the busiest facets' shares
// written on them and a colour bar with numbered ticks (readable without colour).
#include "facet_stats.h"
#include "image.h"
#include "stone.h"

namespace facetlight {

Image facetHeatmap(const Stone& stone, const FacetStats& stats);

}  // namespace facetlight
