#include "io/cutting_sheet.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "io/gemcad_design.h"
#include "io/gemcad_writer.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

// Each facet's tier, for a stone cut from its design: facets are named after the design's planes.
std::vector<size_t> tiersByPlaneName(const Stone& stone, const GemCadDesign& design) {
    std::map<std::string, size_t> tierOfPlane;
    size_t t = 0, left = design.tiers.empty() ? 0 : design.tiers[0].facets.size();
    for (const NamedPlane& p : gemCadPlanes(design)) {
        while (left == 0) left = design.tiers[++t].facets.size();
        tierOfPlane[p.name] = t;
        --left;
    }
    std::vector<size_t> tiers;
    for (const Facet& f : stone.facets) {
        const auto it = tierOfPlane.find(f.name);
        tiers.push_back(it == tierOfPlane.end() ? SIZE_MAX : it->second);
    }
    return tiers;
}

}  // namespace

std::string gearIndexText(double index, int gear) {
    const double teeth = std::abs(gear);
    index = std::fmod(index, teeth);
    if (index <= 0) index += teeth;
    std::string s = formatNumber("%.4f", index);
    while (s.back() == '0') s.pop_back();
    if (s.back() == '.') s.pop_back();
    return s.size() == 1 ? "0" + s : s;  // GemCad writes two digits: 03
}

std::optional<CuttingSheet> cuttingSheet(const Stone& stone) {
    GemCadDesign design;
    std::vector<size_t> tierOf;
    CuttingSheet sheet;
    if (stone.design) {
        design = *stone.design;
        tierOf = tiersByPlaneName(stone, design);
        sheet.source = "GemCad design";
    } else {
        if (!stone.convex) return std::nullopt;
        design = gemCadDesignOf(stone, 96, &tierOf);
        sheet.source = "measured from the mesh";
    }
    sheet.gear = design.gear;
    sheet.gearOffset = design.gearOffset;
    sheet.symmetry = design.symmetry;
    sheet.mirror = design.mirror;
    sheet.refractiveIndex = design.refractiveIndex;
    sheet.headers = design.headers;
    sheet.footnotes = design.footnotes;
    std::vector<double> slopeSum(design.tiers.size(), 0);
    for (const GemCadTier& tier : design.tiers) {
        SheetTier s;
        s.name = tier.name;
        s.angleDeg = tier.angleDeg;
        s.distance = tier.distance;
        for (const GemCadFacet& f : tier.facets) s.indices.push_back(f.index);
        s.instructions = tier.instructions;
        s.facets = tier.facets.size();
        sheet.tiers.push_back(std::move(s));
    }
    // The slope from +z or -z, on the tier's own side (a girdle facet's normal may lean either way by a hair).
    for (size_t i = 0; i < stone.facets.size(); ++i) {
        if (tierOf[i] == SIZE_MAX) continue;
        const Vec3& n = stone.facets[i].normal;
        slopeSum[tierOf[i]] += degrees(std::acos(std::clamp(std::fabs(n.z), 0.0, 1.0)));
        ++sheet.tiers[tierOf[i]].facetsCut;
    }
    for (size_t t = 0; t < sheet.tiers.size(); ++t) {
        SheetTier& tier = sheet.tiers[t];
        if (!tier.facetsCut) continue;
        const double slope = slopeSum[t] / double(tier.facetsCut);
        tier.measuredAngleDeg = std::signbit(tier.angleDeg) ? -slope : slope;
    }
    // Meets: tiers whose facets share an outline edge.
    std::map<std::pair<uint32_t, uint32_t>, std::vector<size_t>> facetsOfEdge;
    for (size_t i = 0; i < stone.facets.size(); ++i) {
        const auto& loop = stone.facets[i].outline;
        for (size_t k = 0; k < loop.size(); ++k)
            facetsOfEdge[std::minmax(loop[k], loop[(k + 1) % loop.size()])].push_back(i);
    }
    std::vector<std::set<size_t>> meets(sheet.tiers.size());
    for (const auto& [edge, facets] : facetsOfEdge)
        for (size_t a : facets)
            for (size_t b : facets)
                if (tierOf[a] != SIZE_MAX && tierOf[b] != SIZE_MAX && tierOf[a] != tierOf[b])
                    meets[tierOf[a]].insert(tierOf[b]);
    for (size_t t = 0; t < sheet.tiers.size(); ++t)
        for (size_t m : meets[t]) sheet.tiers[t].meets.push_back(sheet.tiers[m].name);
    return sheet;
}

nlohmann::json toJson(const CuttingSheet& sheet) {
    nlohmann::json tiers = nlohmann::json::array();
    for (const SheetTier& t : sheet.tiers) {
        nlohmann::json j = {{"name", t.name},
                            {"angle_deg", t.angleDeg},
                            {"side", std::signbit(t.angleDeg) ? "pavilion" : "crown"},
                            {"distance", t.distance},
                            {"indices", t.indices},
                            {"facets", t.facets},
                            {"facets_cut", t.facetsCut},
                            {"meets", t.meets}};
        j["measured_angle_deg"] = t.measuredAngleDeg ? nlohmann::json(*t.measuredAngleDeg) : nlohmann::json();
        if (!t.instructions.empty()) j["instructions"] = t.instructions;
        tiers.push_back(std::move(j));
    }
    nlohmann::json j = {{"source", sheet.source}, {"gear", sheet.gear}, {"gear_offset", sheet.gearOffset},
                        {"symmetry", sheet.symmetry},
                        {"mirror", sheet.mirror}, {"headers", sheet.headers}, {"footnotes", sheet.footnotes},
                        {"tiers", tiers}};
    j["refractive_index"] = sheet.refractiveIndex ? nlohmann::json(*sheet.refractiveIndex) : nlohmann::json();
    return j;
}

std::string cuttingSheetText(const CuttingSheet& sheet) {
    std::string out = "cutting sheet (" + sheet.source + "): " + std::to_string(std::abs(sheet.gear)) +
                      "-tooth gear, " + std::to_string(sheet.symmetry) + "-fold symmetry" +
                      (sheet.mirror ? " with mirror" : "") +
                      (sheet.refractiveIndex ? ", index " + formatNumber("%.3f", *sheet.refractiveIndex) : "") +
                      "\n";
    for (const std::string& h : sheet.headers) out += "  " + h + "\n";
    char line[256];
    std::snprintf(line, sizeof line, "  %-10s %-8s %8s %9s %10s %7s  %s\n", "tier", "side", "angle", "measured",
                  "distance", "facets", "indices; meets");
    out += line;
    for (const SheetTier& t : sheet.tiers) {
        std::string indices;
        for (double i : t.indices) indices += (indices.empty() ? "" : "-") + gearIndexText(i, sheet.gear);
        std::string meets;
        for (const std::string& m : t.meets) meets += (meets.empty() ? "" : ", ") + m;
        const std::string measured =
            t.measuredAngleDeg ? formatNumber("%.2f", std::fabs(*t.measuredAngleDeg)) : std::string("-");
        std::snprintf(line, sizeof line, "  %-10s %-8s %8.2f %9s %10.6f %3zu/%-3zu  ", t.name.c_str(),
                      std::signbit(t.angleDeg) ? "pavilion" : "crown", std::fabs(t.angleDeg), measured.c_str(),
                      t.distance, t.facetsCut, t.facets);
        out += line + indices + (meets.empty() ? "" : "; meets " + meets) +
               (t.instructions.empty() ? "" : "  (" + t.instructions + ")") + "\n";
    }
    for (const std::string& f : sheet.footnotes) out += "  " + f + "\n";
    return out;
}

}  // namespace facetlight
