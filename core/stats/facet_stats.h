#pragma once
// What a trace counts, kept in integers (weighted sums in fixed point) so that adding per-thread or per-rank
// tallies in any order gives the same bits; and its report as JSON (docs/stats-schema.md) and CSV.
#include <algorithm>
#include <array>
#include <cstdint>
#include <ostream>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "stone/stone.h"

namespace facetlight {

// Each facet's counters fill a cache line of their own, so per-thread tallies never share a writable line.
struct alignas(64) FacetCounts {
    uint64_t entering = 0;             // refracted into the stone here
    uint64_t reflected = 0;            // first-surface reflections here
    uint64_t leaving = 0;              // refracted out of the stone here
    uint64_t internalReflections = 0;  // total or partial reflections from inside here
    bool operator==(const FacetCounts&) const = default;
};

constexpr int kHistogramBins = 180;  // 1-degree bins of the exit angle from the viewer's vertical
constexpr int kConeCount = 3;
constexpr std::array<double, kConeCount> kConeDegrees{30, 45, 60};
// Fixed-point scale of the cosine weights: 1e10 photons of weight 1 still fit in 64 bits.
constexpr double kWeightScale = 1073741824.0;  // 2^30

// Binomial standard error of a proportion p over n trials.
double stderrOf(double p, uint64_t n);
// Standard error of a mean over n samples, from the means of the samples and of their squares.
double meanStderr(double mean, double meanSquare, uint64_t n);

// The histogram bin of an exit at cos(angle to the vertical) = cosUp: floor(angle in degrees), at most 179.
// Without acos: a table over cosUp gives the bin within two of the answer, and comparisons with the bin
// boundaries cos(k degrees) finish it.
class ExitAngleBins {
  public:
    ExitAngleBins();
    int operator()(float cosUp) const {
        const float x = std::clamp(cosUp, -1.0f, 1.0f);
        int bin = guess_[std::min(kGuesses - 1, int((x + 1) * (kGuesses / 2)))];
        bin += x <= bound_[bin + 1];
        bin += x <= bound_[bin + 1];
        return bin;
    }

  private:
    static constexpr int kGuesses = 8192;
    std::array<float, kHistogramBins + 2> bound_;  // cos(k degrees); -2 past the last bin so it never grows
    std::array<uint8_t, kGuesses> guess_;          // the bin at the top of each of kGuesses slices of cosUp
};

struct alignas(64) FacetStats {
    explicit FacetStats(size_t facetCount = 0) : facets(facetCount) {}

    uint64_t photons = 0, hit = 0, reflectedAtEntry = 0, entered = 0, exited = 0, trapped = 0;
    uint64_t lost = 0;             // part of `trapped`: the intersector found no way out (rounding)
    uint64_t absorbed = 0;         // of `entered`, absorbed inside (Beer-Lambert; 0 in a clear stone)
    uint64_t crownReturn = 0;      // left through table or crown into the upper hemisphere
    uint64_t crownReflection = 0;  // first-surface reflections off table or crown into the upper hemisphere
    std::array<uint64_t, kConeCount> coneReturn{};  // crown exits within each cone, outside the head cone
    uint64_t weightSum = 0, weightSquareSum = 0;    // cos(angle to vertical) of crown returns, fixed point
    // Exits per 1-degree bin: [0] every exit, [1] through table and crown, [2] through pavilion and girdle.
    std::array<std::array<uint64_t, kHistogramBins>, 3> histogram{};
    std::vector<FacetCounts> facets;

    // Adds another tally of the same stone; the sum does not depend on the order of merging.
    void merge(const FacetStats& other);
    // Every tally in one flat array, and back (a length that does not fit throws Error): a distributed run
    // sums these arrays across ranks, which equals merging the tallies.
    std::vector<uint64_t> tallies() const;
    void setTallies(std::span<const uint64_t> values);
    bool operator==(const FacetStats&) const = default;
};

struct TraceTiming {
    double seconds = 0;
    int threads = 1;
};

// The full answer of a trace (docs/stats-schema.md); `settings` are the job's, as JSON.
nlohmann::json statsToJson(const FacetStats& stats, const Stone& stone, const nlohmann::json& settings,
                           const TraceTiming& timing);
// Adds each region's `share_stderr` and each facet's `leaving_share_stderr` (binomial standard errors over
// `totals.hit`) to a document of statsToJson: the service sends them with the statistics, so that clients
// need not compute them; the document written to disk keeps its format.
void addShareStandardErrors(nlohmann::json& stats);
// The facet table: id,name,region,area,normal_x,normal_y,normal_z,entering,reflected,leaving,
// internal_reflections,leaving_share,leaving_share_stderr.
void writeFacetCsv(std::ostream& out, const FacetStats& stats, const Stone& stone);

}  // namespace facetlight
