#include "colour/cie.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace facetlight {
namespace {

constexpr int kRows = 81;  // 380 to 780 nm every 5 nm

// The CIE 1931 2-degree standard observer, x-bar, y-bar, z-bar every 5 nm (CIE 015:2018 table; the CIE's
// data set "CIE 1931 colour-matching functions, 2 degree observer", DOI 10.25039/CIE.DS.xvudnb9b, read at its
// 5 nm rows).
constexpr std::array<std::array<double, 3>, kRows> kCmf{{
    {0.001368, 0.000039, 0.006450001},
    {0.002236, 0.000064, 0.01054999},
    {0.004243, 0.00012, 0.02005001},
    {0.00765, 0.000217, 0.03621},
    {0.01431, 0.000396, 0.06785001},
    {0.02319, 0.00064, 0.1102},
    {0.04351, 0.00121, 0.2074},
    {0.07763, 0.00218, 0.3713},
    {0.13438, 0.004, 0.6456},
    {0.21477, 0.0073, 1.0390501},
    {0.2839, 0.0116, 1.3856},
    {0.3285, 0.01684, 1.62296},
    {0.34828, 0.023, 1.74706},
    {0.34806, 0.0298, 1.7826},
    {0.3362, 0.038, 1.77211},
    {0.3187, 0.048, 1.7441},
    {0.2908, 0.06, 1.6692},
    {0.2511, 0.0739, 1.5281},
    {0.19536, 0.09098, 1.28764},
    {0.1421, 0.1126, 1.0419},
    {0.09564, 0.13902, 0.8129501},
    {0.05795001, 0.1693, 0.6162},
    {0.03201, 0.20802, 0.46518},
    {0.0147, 0.2586, 0.3533},
    {0.0049, 0.323, 0.272},
    {0.0024, 0.4073, 0.2123},
    {0.0093, 0.503, 0.1582},
    {0.0291, 0.6082, 0.1117},
    {0.06327, 0.71, 0.07824999},
    {0.1096, 0.7932, 0.05725001},
    {0.1655, 0.862, 0.04216},
    {0.2257499, 0.9148501, 0.02984},
    {0.2904, 0.954, 0.0203},
    {0.3597, 0.9803, 0.0134},
    {0.4334499, 0.9949501, 0.008749999},
    {0.5120501, 1.0, 0.005749999},
    {0.5945, 0.995, 0.0039},
    {0.6784, 0.9786, 0.002749999},
    {0.7621, 0.952, 0.0021},
    {0.8425, 0.9154, 0.0018},
    {0.9163, 0.87, 0.001650001},
    {0.9786, 0.8163, 0.0014},
    {1.0263, 0.757, 0.0011},
    {1.0567, 0.6949, 0.001},
    {1.0622, 0.631, 0.0008},
    {1.0456, 0.5668, 0.0006},
    {1.0026, 0.503, 0.00034},
    {0.9384, 0.4412, 0.00024},
    {0.8544499, 0.381, 0.00019},
    {0.7514, 0.321, 0.0001},
    {0.6424, 0.265, 0.00005},
    {0.5419, 0.217, 0.00003},
    {0.4479, 0.175, 0.00002},
    {0.3608, 0.1382, 0.00001},
    {0.2835, 0.107, 0},
    {0.2187, 0.0816, 0},
    {0.1649, 0.061, 0},
    {0.1212, 0.04458, 0},
    {0.0874, 0.032, 0},
    {0.0636, 0.0232, 0},
    {0.04677, 0.017, 0},
    {0.0329, 0.01192, 0},
    {0.0227, 0.00821, 0},
    {0.01584, 0.005723, 0},
    {0.01135916, 0.004102, 0},
    {0.008110916, 0.002929, 0},
    {0.005790346, 0.002091, 0},
    {0.004109457, 0.001484, 0},
    {0.002899327, 0.001047, 0},
    {0.00204919, 0.00074, 0},
    {0.001439971, 0.00052, 0},
    {0.000999949, 0.0003611, 0},
    {0.000690079, 0.0002492, 0},
    {0.000476021, 0.0001719, 0},
    {0.000332301, 0.00012, 0},
    {0.000234826, 0.0000848, 0},
    {0.000166151, 0.00006, 0},
    {0.000117413, 0.0000424, 0},
    {0.0000830753, 0.00003, 0},
    {0.0000587065, 0.0000212, 0},
    {0.0000415099, 0.00001499, 0},
}};

// CIE standard illuminant D65, relative spectral power every 5 nm, 100 at 560 nm (CIE 015:2018 table; the
// CIE's data set "CIE standard illuminant D65", DOI 10.25039/CIE.DS.hjfjmt59, read at its 5 nm rows).
constexpr std::array<double, kRows> kD65{
    49.9755, 52.3118, 54.6482, 68.7015, 82.7549, 87.1204, 91.486,  92.4589, 93.4318, 90.057,  86.6823,
    95.7736, 104.865, 110.936, 117.008, 117.41,  117.812, 116.336, 114.861, 115.392, 115.923, 112.367,
    108.811, 109.082, 109.354, 108.578, 107.802, 106.296, 104.79,  106.239, 107.689, 106.047, 104.405,
    104.225, 104.046, 102.023, 100.0,   98.1671, 96.3342, 96.0611, 95.788,  92.2368, 88.6856, 89.3459,
    90.0062, 89.8026, 89.5991, 88.6489, 87.6987, 85.4936, 83.2886, 83.4939, 83.6992, 81.863,  80.0268,
    80.1207, 80.2146, 81.2462, 82.2778, 80.281,  78.2842, 74.0027, 69.7213, 70.6652, 71.6091, 72.979,
    74.349,  67.9765, 61.604,  65.7448, 69.8856, 72.4863, 75.087,  69.3398, 63.5927, 55.0054, 46.4182,
    56.6118, 66.8054, 65.0941, 63.3828};

// CIE standard illuminant A (CIE 015:2018, 3.1): a Planckian radiator at 2856 K on the IPTS-68 scale, written
// as the CIE writes it, with c2 = 1.435e7 nm K and T = 2848 K, 100 at 560 nm.
double illuminantA(double nm) {
    constexpr double c2OverT = 1.435e7 / 2848;
    return 100 * std::pow(560 / nm, 5) * std::expm1(c2OverT / 560) / std::expm1(c2OverT / nm);
}

double rowWavelength(int row) {
    return kCieFirstNm + kCieStepNm * row;
}

}  // namespace

Vec3 cieXyz(double wavelengthNm) {
    // Catmull-Rom between the table's rows (the rows beyond each end repeated), clamped at 0.
    constexpr int last = kRows - 1;
    const double x = (wavelengthNm - kCieFirstNm) / kCieStepNm;
    if (!(x >= 0 && x <= last)) return {};
    const int i = std::min(int(x), last - 1);
    const double t = x - i;
    const auto row = [&](int k) { return kCmf[size_t(std::clamp(k, 0, last))]; };
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

double illuminantPower(Illuminant illuminant, double wavelengthNm) {
    const double x = (wavelengthNm - kCieFirstNm) / kCieStepNm;
    if (!(x >= 0 && x <= kRows - 1)) return 0;
    if (illuminant == Illuminant::A) return illuminantA(wavelengthNm);
    const int i = std::min(int(x), kRows - 2);
    const double t = x - i;
    return kD65[size_t(i)] * (1 - t) + kD65[size_t(i) + 1] * t;
}

Vec3 tristimulus(Illuminant illuminant, const std::function<double(double)>& factor) {
    Vec3 sum;
    double white = 0;
    for (int row = 0; row < kRows; ++row) {
        const double l = rowWavelength(row);
        const double s = illuminant == Illuminant::A ? illuminantA(l) : kD65[size_t(row)];
        const auto& c = kCmf[size_t(row)];
        sum += Vec3{c[0], c[1], c[2]} * (s * factor(l));
        white += s * c[1];
    }
    return sum / white;
}

Vec3 whitePoint(Illuminant illuminant) {
    return tristimulus(illuminant, [](double) { return 1.0; });
}

}  // namespace facetlight
