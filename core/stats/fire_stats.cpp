#include "stats/fire_stats.h"

#include <cmath>
#include <string>

#include "stats/facet_stats.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;

// Calls f on every tally of s, in one fixed order.
template <class Stats, class F>
void forEachTally(Stats& s, F&& f) {
    for (auto* v : {&s.photons, &s.hit, &s.pairs, &s.split, &s.separationSum, &s.separationSquareSum,
                    &s.coloured, &s.colouredWeightSum, &s.colouredWeightSquareSum})
        f(*v);
    for (auto& v : s.crownReturn) f(v);
    for (auto& row : s.histogram)
        for (auto& v : row) f(v);
    for (auto& v : s.colouredByFacet) f(v);
}

double ratio(uint64_t count, uint64_t of) {
    return of ? double(count) / double(of) : 0.0;
}

}  // namespace

FireExitBins::FireExitBins() {
    for (size_t k = 0; k < edges_.size(); ++k) edges_[k] = std::cos(radians(double(k + 1) * kFireExitBinDeg));
}

void FireStats::merge(const FireStats& o) {
    if (o.colouredByFacet.size() != colouredByFacet.size())
        throw Error("cannot merge fire statistics of different stones");
    std::vector<uint64_t> sum = tallies();
    const std::vector<uint64_t> other = o.tallies();
    for (size_t i = 0; i < sum.size(); ++i) sum[i] += other[i];
    setTallies(sum);
}

std::vector<uint64_t> FireStats::tallies() const {
    std::vector<uint64_t> out;
    forEachTally(*this, [&](uint64_t v) { out.push_back(v); });
    return out;
}

void FireStats::setTallies(std::span<const uint64_t> values) {
    size_t count = 0;
    forEachTally(*this, [&](uint64_t) { ++count; });
    if (values.size() != count)
        throw Error("fire statistics of a different stone: tally count does not match");
    size_t i = 0;
    forEachTally(*this, [&](uint64_t& v) { v = values[i++]; });
}

json fireToJson(const FireStats& s, const Stone& stone, double pupilDeg, double headConeDeg) {
    if (s.colouredByFacet.size() != stone.facets.size())
        throw Error("fire statistics do not belong to stone '" + stone.name + "'");
    const uint64_t n = s.hit;
    json fire = {{"wavelengths_nm", kFireWavelengthsNm},
                 {"red_nm", kFireWavelengthsNm[kFireRed]},
                 {"blue_nm", kFireWavelengthsNm[kFireBlue]},
                 {"pupil_deg", pupilDeg},
                 {"head_cone_deg", headConeDeg},
                 {"photons", s.photons},
                 {"hit", s.hit},
                 {"pairs", s.pairs},
                 {"split", s.split},
                 {"coloured", s.coloured}};
    auto share = [&](const std::string& name, uint64_t count) {
        const double p = ratio(count, n);
        fire[name] = p;
        fire[name + "_stderr"] = stderrOf(p, n);
    };
    share("pair_share", s.pairs);
    share("split_share", s.split);
    share("coloured_share", s.coloured);

    const double mean = s.pairs ? double(s.separationSum) / kSeparationScale / double(s.pairs) : 0.0;
    const double meanSquare =
        s.pairs ? double(s.separationSquareSum) / kSeparationScale / double(s.pairs) : 0.0;
    fire["mean_separation_deg"] = mean;
    fire["mean_separation_deg_stderr"] = meanStderr(mean, meanSquare, s.pairs);

    const double w = n ? double(s.colouredWeightSum) / kWeightScale / double(n) : 0.0;
    const double w2 = n ? double(s.colouredWeightSquareSum) / kWeightScale / double(n) : 0.0;
    fire["coloured_return_weighted"] = w;
    fire["coloured_return_weighted_stderr"] = meanStderr(w, w2, n);

    json bands = json::array();
    for (int b = 0; b < kFireBands; ++b) {
        const double p = ratio(s.crownReturn[b], n);
        bands.push_back({{"wavelength_nm", kFireWavelengthsNm[b]},
                         {"crown_return", p},
                         {"crown_return_stderr", stderrOf(p, n)}});
    }
    fire["bands"] = bands;

    fire["histogram"] = {{"exit_bin_degrees", kFireExitBinDeg},
                         {"separation_bin_degrees", kFireSeparationBinDeg},
                         {"counts", s.histogram}};

    json facets = json::array();
    for (size_t i = 0; i < stone.facets.size(); ++i) {
        const double p = ratio(s.colouredByFacet[i], s.coloured);
        facets.push_back({{"id", stone.facets[i].id},
                          {"coloured", s.colouredByFacet[i]},
                          {"share", p},
                          {"share_stderr", stderrOf(p, s.coloured)}});
    }
    fire["facets"] = facets;
    return fire;
}

}  // namespace facetlight
