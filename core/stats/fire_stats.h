#pragma once
// What a fire trace counts (trace/fire_trace.h), kept in integers (separations and weights in fixed point) so
// that adding per-thread or per-rank tallies in any order gives the same bits; and its report, the `fire`
// member of stats.json (docs/stats-schema.md; the figures are defined in docs/physics.md).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/geometry.h"
#include "stone/stone.h"

namespace facetlight {

// The bands each photon is followed at: the Fraunhofer C, D and F lines (docs/optics.md), red to blue.
constexpr int kFireBands = 3;
constexpr std::array<double, kFireBands> kFireWavelengthsNm{656.27, 589.29, 486.13};
constexpr int kFireRed = 0, kFireBlue = kFireBands - 1;

// The histogram of separation against exit angle: 5-degree bins of the angle from the vertical (0-90), and
// 0.1-degree bins of the red-blue separation, the last also holding everything wider.
constexpr int kFireExitBins = 18;
constexpr double kFireExitBinDeg = 5;
constexpr int kFireSeparationBins = 60;
constexpr double kFireSeparationBinDeg = 0.1;
// Fixed point of the separations: 2^20 per degree (1e10 photons of 1 degree still fit in 64 bits).
constexpr double kSeparationScale = 1048576.0;

// The histogram's exit-angle bin of a pair whose bisector makes cos(angle to vertical) = cosUp with the
// vertical: int(degrees(acos(cosUp)) / kFireExitBinDeg), the last bin also holding everything wider. Found
// by comparing cosUp with the bins' edges, without acos, except within a hair of an edge, where the
// formula's own rounding decides: the formula's bin for every cosUp.
class FireExitBins {
  public:
    FireExitBins();
    int operator()(double cosUp) const {
        int bin = 0;
        bool nearEdge = false;
        for (const double edge : edges_) {
            bin += cosUp < edge;
            nearEdge |= std::abs(cosUp - edge) < kHair;
        }
        return nearEdge ? formula(cosUp) : bin;
    }
    static int formula(double cosUp) {
        return std::min(kFireExitBins - 1, int(degrees(std::acos(cosUp)) / kFireExitBinDeg));
    }

  private:
    // Far above the formula's rounding, a few ulps of the angle, times the steepest slope of cos at an edge.
    static constexpr double kHair = 1e-9;
    std::array<double, kFireExitBins - 1> edges_;  // cos(k kFireExitBinDeg), k = 1, 2, ...
};

struct alignas(64) FireStats {
    explicit FireStats(size_t facetCount = 0) : colouredByFacet(facetCount) {}

    uint64_t photons = 0, hit = 0;
    std::array<uint64_t, kFireBands> crownReturn{};  // each band's exits through table or crown, upward
    uint64_t pairs = 0;  // red and blue both out through table or crown, upward, along the same facet path
    uint64_t split = 0;  // one of them out so, the other elsewhere or along another path
    uint64_t separationSum = 0, separationSquareSum = 0;  // red-blue angle of the pairs; square >> 20
    uint64_t coloured = 0;                                // pairs further apart than the pupil's angle
    // The coloured pairs' cos(angle to vertical) outside the head cone, in kWeightScale fixed point.
    uint64_t colouredWeightSum = 0, colouredWeightSquareSum = 0;
    std::array<std::array<uint64_t, kFireSeparationBins>, kFireExitBins> histogram{};  // pairs
    std::vector<uint64_t> colouredByFacet;  // coloured pairs by the facet they left through

    // Adds another tally of the same stone; the sum does not depend on the order of merging.
    void merge(const FireStats& other);
    // Every tally in one flat array, and back (a length that does not fit throws Error), for the ranks' sum.
    std::vector<uint64_t> tallies() const;
    void setTallies(std::span<const uint64_t> values);
    bool operator==(const FireStats&) const = default;
};

// The `fire` member of stats.json: `pupilDeg` the angle the pupil spans, `headConeDeg` the head cone of the
// light (FireSettings::pupilAngleDeg(), LightSettings::headShadowDeg).
nlohmann::json fireToJson(const FireStats& stats, const Stone& stone, double pupilDeg, double headConeDeg);

}  // namespace facetlight
