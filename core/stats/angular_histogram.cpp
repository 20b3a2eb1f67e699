#include "stats/angular_histogram.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace facetlight {

void AngularHistogram::add(const Vec3& dir) {
    ++total;
    if (dir.z <= 0) return;
    const int theta = std::min(kThetaBins - 1, int(degrees(std::acos(std::min(1.0, dir.z)))));
    double phi = degrees(std::atan2(dir.y, dir.x));
    if (phi < 0) phi += 360;
    const int p = std::min(kPhiBins - 1, int(phi / (360.0 / kPhiBins)));
    ++counts[size_t(theta) * kPhiBins + p];
}

void AngularHistogram::merge(const AngularHistogram& o) {
    for (size_t i = 0; i < counts.size(); ++i) counts[i] += o.counts[i];
    total += o.total;
}

std::vector<uint64_t> AngularHistogram::tallies() const {
    std::vector<uint64_t> out(counts);
    out.push_back(total);
    return out;
}

void AngularHistogram::setTallies(const std::vector<uint64_t>& values) {
    if (values.size() != counts.size() + 1) throw Error("angular histogram tallies of the wrong length");
    std::copy(values.begin(), values.end() - 1, counts.begin());
    total = values.back();
}

}  // namespace facetlight
