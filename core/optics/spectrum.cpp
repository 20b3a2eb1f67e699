#include "optics/spectrum.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace facetlight {
namespace {

// The CIE 1931 2-degree standard observer, x-bar, y-bar, z-bar every 10 nm from 380 to 780 nm (CIE 015:2004,
// table T.4; the same values as the CVRL's "CIE 1931 2-deg, XYZ CMFs", cvrl.org).
constexpr double kCmfStart = 380, kCmfStep = 10;
constexpr std::array<std::array<double, 3>, 41> kCie1931{{
    {0.001368, 0.000039, 0.006450}, {0.004243, 0.000120, 0.020050}, {0.014310, 0.000396, 0.067850},
    {0.043510, 0.001210, 0.207400}, {0.134380, 0.004000, 0.645600}, {0.283900, 0.011600, 1.385600},
    {0.348280, 0.023000, 1.747060}, {0.336200, 0.038000, 1.772110}, {0.290800, 0.060000, 1.669200},
    {0.195360, 0.090980, 1.287640}, {0.095640, 0.139020, 0.812950}, {0.032010, 0.208020, 0.465180},
    {0.004900, 0.323000, 0.272000}, {0.009300, 0.503000, 0.158200}, {0.063270, 0.710000, 0.078250},
    {0.165500, 0.862000, 0.042160}, {0.290400, 0.954000, 0.020300}, {0.433450, 0.994950, 0.008750},
    {0.594500, 0.995000, 0.003900}, {0.762100, 0.952000, 0.002100}, {0.916300, 0.870000, 0.001650},
    {1.026300, 0.757000, 0.001100}, {1.062200, 0.631000, 0.000800}, {1.002600, 0.503000, 0.000340},
    {0.854450, 0.381000, 0.000190}, {0.642400, 0.265000, 0.000050}, {0.447900, 0.175000, 0.000020},
    {0.283500, 0.107000, 0.000000}, {0.164900, 0.061000, 0.000000}, {0.087400, 0.032000, 0.000000},
    {0.046770, 0.017000, 0.000000}, {0.022700, 0.008210, 0.000000}, {0.011359, 0.004102, 0.000000},
    {0.005790, 0.002091, 0.000000}, {0.002899, 0.001047, 0.000000}, {0.001440, 0.000520, 0.000000},
    {0.000690, 0.000249, 0.000000}, {0.000332, 0.000120, 0.000000}, {0.000166, 0.000060, 0.000000},
    {0.000083, 0.000030, 0.000000}, {0.000042, 0.000015, 0.000000},
}};

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

Vec3 cieXyz(double wavelengthNm) {
    // Catmull-Rom between the table's rows (the rows beyond each end repeated), clamped at 0: the curve
    // passes through every tabulated value.
    constexpr int last = int(kCie1931.size()) - 1;
    const double x = (wavelengthNm - kCmfStart) / kCmfStep;
    if (!(x >= 0 && x <= last)) return {};
    const int i = std::min(int(x), last - 1);
    const double t = x - i;
    const auto row = [&](int k) { return kCie1931[size_t(std::clamp(k, 0, last))]; };
    const std::array<double, 3> p0 = row(i - 1), p1 = row(i), p2 = row(i + 1), p3 = row(i + 2);
    std::array<double, 3> v;
    for (int c = 0; c < 3; ++c) {
        const double a = -0.5 * p0[c] + 1.5 * p1[c] - 1.5 * p2[c] + 0.5 * p3[c];
        const double b = p0[c] - 2.5 * p1[c] + 2 * p2[c] - 0.5 * p3[c];
        const double d = -0.5 * p0[c] + 0.5 * p2[c];
        v[c] = std::max(0.0, ((a * t + b) * t + d) * t + p1[c]);
    }
    return {v[0], v[1], v[2]};
}

Vec3 xyzToLinearSrgb(const Vec3& c) {
    return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
            -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
            0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

double srgbEncode(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

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
