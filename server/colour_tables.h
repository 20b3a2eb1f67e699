#pragma once
// The CIE tables the colour view sums over (core/colour), for a client that shows a colour of its own (the
// page's absorption swatches): the server's numbers, not a copy of them.
#include <map>
#include <string>

#include <nlohmann/json.hpp>

namespace facetlight::server {

// GET /api/colour/cie: the 5 nm rows of 380-780 nm with x-bar, y-bar, z-bar and the relative power of each
// illuminant, each illuminant's white (Y = 1) and the XYZ to linear sRGB matrix.
nlohmann::json cieTablesJson();

// GET /api/colour/by-transmission: the absorption table that a colour by transmission gives (docs/optics.md,
// "Colour by transmission"), from the query's transmitted_colour ("#rrggbb" or "L*,a*,b*"),
// extraordinary_transmitted_colour and path_mm, as a job's absorption would read them. Throws Error naming
// the parameter at fault.
nlohmann::json absorptionByTransmission(const std::multimap<std::string, std::string>& query);

}  // namespace facetlight::server
