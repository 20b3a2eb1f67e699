#pragma once
// What the table-printing benchmarks share: wall seconds since a time point, and the median of repeated runs.
#include <algorithm>
#include <chrono>
#include <vector>

namespace facetlight::bench {

inline double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace facetlight::bench
