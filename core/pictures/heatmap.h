#pragma once
// The facet diagram: the crown and table seen from above (left) and the pavilion seen from below (right),
// each facet filled by its share of the light leaving the stone (or, the fire view, of the fire), with
// outlines, the share written on every facet that holds it legibly and a colour bar with numbered ticks
// (readable without colour). The scale ends near the largest share of the facets other than the table, so
// that their differences show; a share beyond it (the table's, mostly) is hatched and named under the bar.
#include <vector>

#include <nlohmann/json.hpp>

#include "image/image.h"
#include "stats/facet_stats.h"
#include "stats/fire_stats.h"
#include "stone/stone.h"

namespace facetlight {

Image facetHeatmap(const Stone& stone, const FacetStats& stats);
// The fire view: each facet filled by its share of the fire (the coloured exits of a fire trace).
Image fireHeatmap(const Stone& stone, const FireStats& fire);

// Where each facet lies in facetHeatmap's picture, so that a page showing it can tell which facet is under
// the pointer: the outline and centroid in pixels, in drawing order (far facets first; a later facet covers
// an earlier one). Girdle facets are not drawn.
struct HeatmapFacet {
    uint32_t facet;
    int side;  // 0: crown and table, from above; 1: pavilion, from below
    std::vector<Point2> outline;
    Point2 centroid;
};
struct HeatmapLayout {
    int width = 0, height = 0;
    std::vector<HeatmapFacet> facets;
};
HeatmapLayout heatmapLayout(const Stone& stone);
// {"width", "height", "facets": [{"id", "name", "side": "crown"|"pavilion", "points": [[x, y], ...]}]}
// (docs/stats-schema.md, "Heat-map layout").
nlohmann::json toJson(const HeatmapLayout& layout, const Stone& stone);

}  // namespace facetlight
