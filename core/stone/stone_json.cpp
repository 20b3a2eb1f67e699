#include "stone/stone_json.h"

#include <cmath>
#include <string>

#include "stone/proportions.h"

namespace facetlight {

namespace {

nlohmann::json optionalNumber(const std::optional<double>& v) { return v ? nlohmann::json(*v) : nlohmann::json(); }

nlohmann::json vec3Json(const Vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }

// `v` to `decimals` places, written as short decimals (dividing by an exact power of ten gives the double
// nearest the decimal).
nlohmann::json roundedJson(const Vec3& v, int decimals) {
    const double scale = std::pow(10.0, decimals);
    const auto r = [scale](double x) { return std::round(x * scale) / scale; };
    return nlohmann::json::array({r(v.x), r(v.y), r(v.z)});
}

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

nlohmann::json stoneGeometryJson(const Stone& stone, double mmPerUnit) {
    nlohmann::json facets = nlohmann::json::array();
    for (const Facet& f : stone.facets) {
        // To 10 nm: far below any cutter's tolerance, and the file stays small.
        nlohmann::json corners = nlohmann::json::array();
        for (uint32_t v : f.outline) corners.push_back(roundedJson(stone.vertices[v] * mmPerUnit, 5));
        facets.push_back({{"id", f.id},
                          {"name", f.name},
                          {"region", regionName(f.region)},
                          {"normal", roundedJson(f.normal, 9)},
                          {"vertices", std::move(corners)}});
    }
    return {{"name", stone.name},
            {"units", "mm"},
            {"mm_per_unit", mmPerUnit},
            {"frame", "the stone's: girdle plane z = 0, table up (+z), centred on the z axis"},
            {"facets", std::move(facets)}};
}

}  // namespace facetlight
