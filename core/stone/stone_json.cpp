#include "stone/stone_json.h"

namespace facetlight {

namespace {

nlohmann::json optionalNumber(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

nlohmann::json vec3Json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

}  // namespace

nlohmann::json proportionsJson(const Proportions& p) {
    return {{"length", p.length},
            {"width", p.width},
            {"diameter", p.diameter},
            {"length_to_width", p.width > 0 ? p.length / p.width : 0.0},
            {"table_pct", optionalNumber(p.tablePct)},
            {"crown_height_pct", optionalNumber(p.crownHeightPct)},
            {"pavilion_depth_pct", optionalNumber(p.pavilionDepthPct)},
            {"girdle_pct", optionalNumber(p.girdlePct)},
            {"girdle_thickest_pct", optionalNumber(p.girdleThickestPct)},
            {"total_depth_pct", optionalNumber(p.totalDepthPct)},
            {"crown_angle_deg", optionalNumber(p.crownAngleDeg)},
            {"pavilion_angle_deg", optionalNumber(p.pavilionAngleDeg)},
            {"star_angle_deg", optionalNumber(p.starAngleDeg)},
            {"upper_half_angle_deg", optionalNumber(p.upperHalfAngleDeg)},
            {"lower_half_angle_deg", optionalNumber(p.lowerHalfAngleDeg)},
            {"star_pct", optionalNumber(p.starPct)},
            {"lower_half_pct", optionalNumber(p.lowerHalfPct)}};
}

nlohmann::json stoneSummaryJson(const Stone& stone) {
    nlohmann::json regions = nlohmann::json::object();
    for (int r = 0; r < kRegionCount; ++r) regions[std::string(regionName(Region(r)))] = stone.facetCount(Region(r));
    return {
        {"name", stone.name},
        {"facet_count", stone.facets.size()},
        {"triangles", stone.triangles.size()},
        {"vertices", stone.vertices.size()},
        {"convex", stone.convex},
        {"regions", regions},
        {"proportions", proportionsJson(stone.proportions)},
        {"warnings", stone.warnings},
    };
}

nlohmann::json stoneJson(const Stone& stone) {
    nlohmann::json j = stoneSummaryJson(stone);
    nlohmann::json facets = nlohmann::json::array();
    for (const auto& f : stone.facets)
        facets.push_back({{"id", f.id},
                          {"name", f.name},
                          {"region", regionName(f.region)},
                          {"area", f.area},
                          {"normal", vec3Json(f.normal)},
                          {"centroid", vec3Json(f.centroid)}});
    j["facets"] = std::move(facets);
    return j;
}

}  // namespace facetlight
