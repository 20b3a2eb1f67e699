#include "stats/facet_stats.h"

#include <cmath>
#include <string>

#include "stone/stone_json.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;

double share(uint64_t count, uint64_t of) {
    return of ? double(count) / double(of) : 0.0;
}

json meshJson(const Stone& stone) {
    return {{"name", stone.name},
            {"facets", stone.facets.size()},
            {"triangles", stone.triangles.size()},
            {"convex", stone.convex},
            {"proportions", proportionsJson(stone.proportions)},
            {"frame", frameJson(stone.frame)}};
}

json histogramJson(const std::array<uint64_t, kHistogramBins>& h) {
    return json(h);
}

}  // namespace

double stderrOf(double p, uint64_t n) {
    return n ? std::sqrt(std::max(0.0, p * (1 - p)) / double(n)) : 0.0;
}

double meanStderr(double mean, double meanSquare, uint64_t n) {
    return n ? std::sqrt(std::max(0.0, meanSquare - mean * mean) / double(n)) : 0.0;
}

ExitAngleBins::ExitAngleBins() {
    for (int k = 0; k <= kHistogramBins; ++k) bound_[k] = float(std::cos(radians(k)));
    bound_[kHistogramBins] = bound_[kHistogramBins + 1] = -2;
    for (int j = 0; j < kGuesses; ++j) {
        const double top = std::min(1.0, -1 + 2.0 * (j + 1) / kGuesses);
        int bin = 0;
        while (bin + 1 < kHistogramBins && top <= double(bound_[bin + 1])) ++bin;
        guess_[j] = uint8_t(bin);
    }
}

void FacetStats::merge(const FacetStats& o) {
    if (o.facets.size() != facets.size()) throw Error("cannot merge statistics of different stones");
    photons += o.photons;
    hit += o.hit;
    reflectedAtEntry += o.reflectedAtEntry;
    entered += o.entered;
    exited += o.exited;
    trapped += o.trapped;
    lost += o.lost;
    absorbed += o.absorbed;
    crownReturn += o.crownReturn;
    crownReflection += o.crownReflection;
    for (int i = 0; i < kConeCount; ++i) coneReturn[i] += o.coneReturn[i];
    weightSum += o.weightSum;
    weightSquareSum += o.weightSquareSum;
    for (size_t h = 0; h < histogram.size(); ++h) {
        for (int b = 0; b < kHistogramBins; ++b) histogram[h][b] += o.histogram[h][b];
    }
    for (size_t i = 0; i < facets.size(); ++i) {
        facets[i].entering += o.facets[i].entering;
        facets[i].reflected += o.facets[i].reflected;
        facets[i].leaving += o.facets[i].leaving;
        facets[i].internalReflections += o.facets[i].internalReflections;
    }
}

namespace {

// Calls f on every tally of s, in one fixed order.
template <class Stats, class F>
void forEachTally(Stats& s, F&& f) {
    for (auto* v : {&s.photons, &s.hit, &s.reflectedAtEntry, &s.entered, &s.exited, &s.trapped, &s.lost,
                    &s.crownReturn, &s.crownReflection, &s.weightSum, &s.weightSquareSum, &s.absorbed})
        f(*v);
    for (auto& v : s.coneReturn) f(v);
    for (auto& h : s.histogram)
        for (auto& v : h) f(v);
    for (auto& c : s.facets) {
        f(c.entering);
        f(c.reflected);
        f(c.leaving);
        f(c.internalReflections);
    }
}

}  // namespace

std::vector<uint64_t> FacetStats::tallies() const {
    std::vector<uint64_t> out;
    forEachTally(*this, [&](uint64_t v) { out.push_back(v); });
    return out;
}

void FacetStats::setTallies(std::span<const uint64_t> values) {
    size_t count = 0;
    forEachTally(*this, [&](uint64_t) { ++count; });
    if (values.size() != count) throw Error("statistics of a different stone: tally count does not match");
    size_t i = 0;
    forEachTally(*this, [&](uint64_t& v) { v = values[i++]; });
}

json statsToJson(const FacetStats& s, const Stone& stone, const json& settings, const TraceTiming& timing) {
    if (s.facets.size() != stone.facets.size())
        throw Error("statistics do not belong to stone '" + stone.name + "'");
    const uint64_t n = s.hit;

    json totals = {
        {"photons", s.photons}, {"hit", s.hit},          {"reflected_at_entry", s.reflectedAtEntry},
        {"entered", s.entered}, {"exited", s.exited},    {"trapped", s.trapped},
        {"lost", s.lost},       {"absorbed", s.absorbed}};
    auto figure = [&](const std::string& name, double p) {
        totals[name] = p;
        totals[name + "_stderr"] = stderrOf(p, n);
    };
    figure("trapped_share", share(s.trapped, n));
    figure("absorbed_share", share(s.absorbed, n));
    figure("crown_return", share(s.crownReturn, n));
    figure("crown_return_with_reflection", share(s.crownReturn + s.crownReflection, n));
    const double w = n ? double(s.weightSum) / kWeightScale / double(n) : 0.0;
    const double w2 = n ? double(s.weightSquareSum) / kWeightScale / double(n) : 0.0;
    totals["weighted_return"] = w;
    totals["weighted_return_stderr"] = meanStderr(w, w2, n);
    for (int c = 0; c < kConeCount; ++c) {
        figure("cone_return_" + std::to_string(int(kConeDegrees[c])), share(s.coneReturn[c], n));
    }

    std::array<uint64_t, kRegionCount> regionLeaving{};
    json facets = json::array();
    for (size_t i = 0; i < stone.facets.size(); ++i) {
        const Facet& f = stone.facets[i];
        const FacetCounts& c = s.facets[i];
        regionLeaving[size_t(f.region)] += c.leaving;
        facets.push_back({{"id", f.id},
                          {"name", f.name},
                          {"region", regionName(f.region)},
                          {"area", f.area},
                          {"normal", {f.normal.x, f.normal.y, f.normal.z}},
                          {"entering", c.entering},
                          {"reflected", c.reflected},
                          {"leaving", c.leaving},
                          {"internal_reflections", c.internalReflections},
                          {"leaving_share", share(c.leaving, n)}});
    }
    figure("leakage",
           share(regionLeaving[size_t(Region::Pavilion)] + regionLeaving[size_t(Region::Girdle)], n));

    json regions = json::object();
    for (int r = 0; r < kRegionCount; ++r) {
        regions[std::string(regionName(Region(r)))] = {{"leaving", regionLeaving[r]},
                                                       {"share", share(regionLeaving[r], n)}};
    }

    return {{"mesh", meshJson(stone)},
            {"settings", settings},
            {"timing",
             {{"seconds", timing.seconds},
              {"photons_per_second", timing.seconds > 0 ? double(s.photons) / timing.seconds : 0.0},
              {"threads", timing.threads}}},
            {"totals", totals},
            {"regions", regions},
            {"facets", facets},
            {"exit_angle_histogram",
             {{"bin_degrees", 1},
              {"all", histogramJson(s.histogram[0])},
              {"crown", histogramJson(s.histogram[1])},
              {"pavilion", histogramJson(s.histogram[2])}}}};
}

void addShareStandardErrors(json& stats) {
    const uint64_t n = stats.at("totals").at("hit").get<uint64_t>();
    for (auto& [name, region] : stats.at("regions").items())
        region["share_stderr"] = stderrOf(region.at("share").get<double>(), n);
    for (json& facet : stats.at("facets"))
        facet["leaving_share_stderr"] = stderrOf(facet.at("leaving_share").get<double>(), n);
}

void writeFacetCsv(std::ostream& out, const FacetStats& s, const Stone& stone) {
    if (s.facets.size() != stone.facets.size())
        throw Error("statistics do not belong to stone '" + stone.name + "'");
    out << "id,name,region,area,normal_x,normal_y,normal_z,entering,reflected,leaving,internal_reflections,"
           "leaving_share,leaving_share_stderr\n";
    out.precision(9);
    for (size_t i = 0; i < stone.facets.size(); ++i) {
        const Facet& f = stone.facets[i];
        const FacetCounts& c = s.facets[i];
        // Names come from files: quote them, doubling embedded quotes (RFC 4180).
        std::string name = "\"";
        for (char ch : f.name) name += ch == '"' ? std::string("\"\"") : std::string(1, ch);
        name += "\"";
        out << f.id << ',' << name << ',' << regionName(f.region) << ',' << f.area << ',' << f.normal.x << ','
            << f.normal.y << ',' << f.normal.z << ',' << c.entering << ',' << c.reflected << ',' << c.leaving
            << ',' << c.internalReflections << ',' << share(c.leaving, s.hit) << ','
            << stderrOf(share(c.leaving, s.hit), s.hit) << '\n';
    }
}

}  // namespace facetlight
