#pragma once
// The JSON description of a stone shared by `facetlight info`, the statistics and the service's mesh list.
#include <nlohmann/json.hpp>

#include "stone/stone.h"

namespace facetlight {

// length, width, diameter, length_to_width and the trade proportions (null where one does not apply).
nlohmann::json proportionsJson(const Proportions& p);
// What was done to the file's geometry (docs/gemcad.md): file_orientation, table_facet and turned_deg,
// long_axis_turned, shift.
nlohmann::json frameJson(const StoneFrame& frame);
// name, facet and triangle counts, convex, regions (facet count per region), proportions, frame, a design's
// tiers, warnings.
nlohmann::json stoneSummaryJson(const Stone& stone);
// The summary plus `facets`: id, name, region, area, normal, centroid.
nlohmann::json stoneJson(const Stone& stone);
// The stone as traced, for a 3-D view (`stone.json`, docs/stats-schema.md): in the stone's frame and in mm
// (`mmPerUnit`: the trace's scale, size_mm over the girdle diameter), each facet's id, name, region, outward
// normal and its outline's corners, counter-clockwise seen from outside.
nlohmann::json stoneGeometryJson(const Stone& stone, double mmPerUnit);

}  // namespace facetlight
