#pragma once
// The JSON description of a stone shared by `facetlight info`, the statistics and the service's mesh list.
#include <nlohmann/json.hpp>

#include "stone/stone.h"

namespace facetlight {

// length, width, diameter, length_to_width and the trade proportions (null where one does not apply).
nlohmann::json proportionsJson(const Proportions& p);
// name, facet and triangle counts, convex, regions (facet count per region), proportions, warnings.
nlohmann::json stoneSummaryJson(const Stone& stone);
// The summary plus `facets`: id, name, region, area, normal, centroid.
nlohmann::json stoneJson(const Stone& stone);

}  // namespace facetlight
