#include "optics/spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "colour/colour_space.h"

namespace facetlight {
namespace {

// The colour-matching functions tabulated at 1 nm over the visible range, with their running sums.
struct Table {
    static constexpr int kSteps = int(kMaxWavelength - kMinWavelength);
    std::array<Vec3, kSteps> rgb;          // linear sRGB of 1 nm of equal-energy light, bin centres
    std::array<double, kSteps + 1> cdf{};  // running sum of x + y + z
    Vec3 white;                            // sum of rgb
    std::array<Vec3, kSteps + 1> photon;   // photonColour() at whole nanometres
    Table() {
        for (int i = 0; i <= kSteps; ++i) photon[i] = xyzToLinearSrgb(cieXyz(kMinWavelength + i));
        for (int i = 0; i < kSteps; ++i) {
            const Vec3 xyz = cieXyz(kMinWavelength + i + 0.5);
            rgb[i] = xyzToLinearSrgb(xyz);
            white += rgb[i];
            cdf[i + 1] = cdf[i] + xyz.x + xyz.y + xyz.z;
        }
        for (Vec3& c : photon) c = {c.x * kSteps / white.x, c.y * kSteps / white.y, c.z * kSteps / white.z};
    }
};

const Table& table() {
    static const Table t;
    return t;
}

}  // namespace

SpectralBands::SpectralBands(int count) {
    const Table& t = table();
    const double total = t.cdf.back();
    edge_.push_back(kMinWavelength);
    int step = 0;
    for (int b = 1; b <= count; ++b) {
        // The band's upper edge where the running sum reaches b / count of the total, interpolated within 1
        // nm.
        const double target = total * b / count;
        while (step < Table::kSteps && t.cdf[step + 1] < target) ++step;
        double edge = kMaxWavelength;
        if (b < count && step < Table::kSteps) {
            const double f = (target - t.cdf[step]) / std::max(1e-300, t.cdf[step + 1] - t.cdf[step]);
            edge = kMinWavelength + step + std::clamp(f, 0.0, 1.0);
        }
        edge_.push_back(std::max(edge, edge_.back()));
    }
    // Each band's colour: the integral of rgb over the band (partial nm steps weighted by overlap).
    for (int b = 0; b < count; ++b) {
        Vec3 sum;
        for (int i = 0; i < Table::kSteps; ++i) {
            const double lo = std::max(edge_[b], kMinWavelength + i),
                         hi = std::min(edge_[b + 1], kMinWavelength + i + 1);
            if (hi > lo) sum += t.rgb[i] * (hi - lo);
        }
        colour_.push_back({sum.x / t.white.x, sum.y / t.white.y, sum.z / t.white.z});
    }
}

Vec3 photonColour(double wavelengthNm) {
    const Table& t = table();
    const double x = std::clamp(wavelengthNm - kMinWavelength, 0.0, double(Table::kSteps));
    const int i = std::min(int(x), Table::kSteps - 1);
    const double f = x - i;
    return t.photon[i] * (1 - f) + t.photon[i + 1] * f;
}

}  // namespace facetlight
