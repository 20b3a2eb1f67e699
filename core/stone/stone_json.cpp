#include "stone/stone_json.h"

#include <string>

#include "stone/proportions.h"

namespace facetlight {

namespace {

nlohmann::json optionalNumber(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

nlohmann::json vec3Json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

}  // namespace

nlohmann::json proportionsJson(const Proportions& p) {
    nlohmann::json j = {{"length", p.length},
                        {"width", p.width},
                        {"diameter", p.diameter},
                        {"length_to_width", p.width > 0 ? p.length / p.width : 0.0}};
    for (const ProportionField& field : kProportionFields)
        j[std::string(field.key)] = optionalNumber(p.*field.member);
    return j;
}

nlohmann::json frameJson(const StoneFrame& frame) {
    nlohmann::json j = {{"file_orientation", frame.fileOrientation}, {"shift", vec3Json(frame.shift)}};
    if (!frame.tableFacet.empty()) j["table_facet"] = frame.tableFacet, j["turned_deg"] = frame.turnedDeg;
    if (frame.longAxisTurned) j["long_axis_turned"] = true;
    return j;
}

// A GemCad design's tiers that a sweep can vary, as its parameters; none for a mesh.
nlohmann::json tiersJson(const Stone& stone) {
    nlohmann::json tiers = nlohmann::json::array();
    if (!stone.design) return tiers;
    for (size_t t = 0; t < stone.design->tiers.size(); ++t) {
        const GemCadTier& tier = stone.design->tiers[t];
        if (!tweakableTier(tier)) continue;
        tiers.push_back({{"parameter", tierParameter(*stone.design, t)},
                         {"angle_deg", std::fabs(tier.angleDeg)},
                         {"side", tier.pavilion() ? "pavilion" : "crown"}});
    }
    return tiers;
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
        {"frame", frameJson(stone.frame)},
        {"tiers", tiersJson(stone)},
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
