#pragma once
// A stone's trade proportions (Proportions, in stone.h): measured once the stone is in the standard frame
// with its regions told apart, and described once for everything that shows them.
#include <array>
#include <optional>
#include <string_view>

#include "stone/stone.h"

namespace facetlight {

// Measures the stone's proportions from its regions and bounds. `scale`: the length of the mesh's extent,
// which the tolerances are fractions of.
Proportions measureProportions(const Stone& stone, double scale);

// A trade proportion, as the terminal (`info`, `cut`) and the JSON (stone_json.h) show it.
struct ProportionField {
    std::string_view key;    // JSON key
    std::string_view label;  // terminal label; scripts/make-meshes reads the figure after it
    std::string_view unit;   // "%" (of the diameter) or "deg"
    std::optional<double> Proportions::*member;
};

// Each trade proportion, in the terminal's order; the sizes (length, width, diameter) come apart.
inline constexpr std::array<ProportionField, 13> kProportionFields{{
    {"table_pct", "table", "%", &Proportions::tablePct},
    {"crown_height_pct", "crown height", "%", &Proportions::crownHeightPct},
    {"girdle_pct", "girdle thinnest", "%", &Proportions::girdlePct},
    {"girdle_thickest_pct", "girdle thickest", "%", &Proportions::girdleThickestPct},
    {"pavilion_depth_pct", "pavilion depth", "%", &Proportions::pavilionDepthPct},
    {"total_depth_pct", "total depth", "%", &Proportions::totalDepthPct},
    {"crown_angle_deg", "crown angle", "deg", &Proportions::crownAngleDeg},
    {"pavilion_angle_deg", "pavilion angle", "deg", &Proportions::pavilionAngleDeg},
    {"star_angle_deg", "star angle", "deg", &Proportions::starAngleDeg},
    {"upper_half_angle_deg", "upper half angle", "deg", &Proportions::upperHalfAngleDeg},
    {"lower_half_angle_deg", "lower half angle", "deg", &Proportions::lowerHalfAngleDeg},
    {"star_pct", "star length", "%", &Proportions::starPct},
    {"lower_half_pct", "lower half length", "%", &Proportions::lowerHalfPct},
}};

}  // namespace facetlight
