#include "io/gemcad_writer.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <tuple>

#include "util/error.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

// The shortest text that reads back as the same double rounded to `decimals`, without trailing zeros.
std::string trimmed(double v, int decimals) {
    std::string s = formatNumber(("%." + std::to_string(decimals) + "f").c_str(), v);
    if (s.find('.') != std::string::npos) {
        while (s.back() == '0') s.pop_back();
        if (s.back() == '.') s.pop_back();
    }
    return s == "-0" ? "0" : s;
}

std::string nameStem(const std::string& name) {
    const size_t cut = name.find_last_of('_');
    if (cut == std::string::npos || cut + 1 == name.size()) return name;
    for (size_t i = cut + 1; i < name.size(); ++i)
        if (!std::isdigit(uint8_t(name[i]))) return name;
    return name.substr(0, cut);
}

}  // namespace

std::string writeGemCad(const GemCadDesign& design) {
    std::string out = "GemCad 5.0\n";
    out += "g " + std::to_string(design.gear) + " " + formatNumber("%.6f", design.gearOffset) + "\n";
    out += "y " + std::to_string(design.symmetry) + (design.mirror ? " y\n" : " n\n");
    if (design.refractiveIndex) out += "I " + formatNumber("%.6f", *design.refractiveIndex) + "\n";
    for (const std::string& h : design.headers) out += "H " + h + "\n";
    for (const GemCadTier& tier : design.tiers) {
        const bool culet = tier.angleDeg == 0 && tier.pavilion();
        out += "a " + formatNumber("%.6f", culet ? 0.0 : tier.angleDeg) + " " +
               formatNumber("%.8f", culet ? -tier.distance : tier.distance);
        bool named = false;
        for (const GemCadFacet& f : tier.facets) {
            out += " " + trimmed(f.index, 6);
            if (!f.name.empty()) out += " n " + f.name, named = true;
        }
        // A tier's own name, where no facet carries it (a name made up from the tier's place is left out).
        if (!named && !tier.name.empty() && tier.name.rfind("tier", 0) != 0) out += " n " + tier.name;
        if (!tier.instructions.empty()) out += " G " + tier.instructions;
        out += "\n";
    }
    for (const std::string& f : design.footnotes) out += "F " + f + "\n";
    return out;
}

GemCadDesign gemCadDesignOf(const Stone& stone, int gear, std::vector<size_t>* tierOfFacet) {
    if (!stone.convex)
        throw Error("stone '" + stone.name + "' is not convex: a GemCad design describes only convex stones");
    GemCadDesign design;
    design.gear = gear;
    design.headers.push_back(stone.name + ", written by facetlight");
    // Tiers in the order their stems first appear; facets keep their order within a tier.
    std::map<std::tuple<std::string, long long, long long>, size_t> tierOf;
    for (const Facet& f : stone.facets) {
        const double slope = degrees(std::acos(std::clamp(std::fabs(f.normal.z), 0.0, 1.0)));
        const double angle = f.normal.z < -1e-9 ? -slope : slope;  // a girdle facet's z may be a hair below 0
        double azimuth = degrees(std::atan2(f.normal.x, f.normal.y));
        if (azimuth < 0) azimuth += 360;
        // A flat facet's azimuth means nothing: index 0.
        const double index = slope < 1e-9 ? 0.0 : std::fmod(azimuth * gear / 360.0, double(gear));
        const auto key = std::make_tuple(nameStem(f.name), std::llround(angle * 1e6), std::llround(f.offset * 1e8));
        auto [it, added] = tierOf.emplace(key, design.tiers.size());
        if (added) {
            GemCadTier tier;
            tier.angleDeg = slope < 1e-9 && f.normal.z < 0 ? -0.0 : angle;  // a culet
            tier.distance = f.offset;
            tier.name = nameStem(f.name);
            design.tiers.push_back(std::move(tier));
        }
        if (tierOfFacet) tierOfFacet->push_back(it->second);
        GemCadTier& tier = design.tiers[it->second];
        tier.facets.push_back({index, tier.facets.empty() ? tier.name : std::string()});
    }
    return design;
}

}  // namespace facetlight
