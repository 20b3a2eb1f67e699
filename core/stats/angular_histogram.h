#pragma once
// Where the light leaving the crown goes: a tally of exit directions over the upper hemisphere (1 degree of
// angle from the vertical by 5 degrees of azimuth). Its polar plot is pictures/angular_plot.h.
#include <cstdint>
#include <vector>

#include "geometry/geometry.h"

namespace facetlight {

struct AngularHistogram {
    static constexpr int kThetaBins = 90;  // 1 degree each, from the vertical
    static constexpr int kPhiBins = 72;    // 5 degrees each, counter-clockwise from +x
    std::vector<uint64_t> counts = std::vector<uint64_t>(size_t(kThetaBins) * kPhiBins);
    uint64_t total = 0;  // directions added, including any below the horizon (not binned)

    // `dir` is a unit vector in the world frame (+z up).
    void add(const Vec3& dir);
    void merge(const AngularHistogram& other);
    // The counts and then the total, flat, for summing across processes; setTallies throws Error on a
    // vector of another length.
    std::vector<uint64_t> tallies() const;
    void setTallies(const std::vector<uint64_t>& values);
    uint64_t count(int theta, int phi) const { return counts[size_t(theta) * kPhiBins + phi]; }
};

}  // namespace facetlight
