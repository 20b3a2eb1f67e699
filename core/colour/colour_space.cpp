#include "colour/colour_space.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace facetlight {

Vec3 xyzToLinearSrgb(const Vec3& c) {
    // The inverse of the matrix from IEC 61966-2-1's primaries and its D65 white, to 7 decimals.
    return {3.2404542 * c.x - 1.5371385 * c.y - 0.4985314 * c.z,
            -0.9692660 * c.x + 1.8760108 * c.y + 0.0415560 * c.z,
            0.0556434 * c.x - 0.2040259 * c.y + 1.0572252 * c.z};
}

Vec3 linearSrgbToXyz(const Vec3& c) {
    // From IEC 61966-2-1's primaries and its D65 white, to 7 decimals; (1, 1, 1) is Y = 1.
    return {0.4124564 * c.x + 0.3575761 * c.y + 0.1804375 * c.z,
            0.2126729 * c.x + 0.7151522 * c.y + 0.0721750 * c.z,
            0.0193339 * c.x + 0.1191920 * c.y + 0.9503041 * c.z};
}

double srgbDecode(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

double srgbEncode(double v) {
    v = std::clamp(v, 0.0, 1.0);
    return v <= 0.0031308 ? 12.92 * v : 1.055 * std::pow(v, 1 / 2.4) - 0.055;
}

double Lab::chroma() const {
    return std::hypot(a, b);
}

double Lab::hueDeg() const {
    const double h = std::atan2(b, a) * 180 / std::numbers::pi;
    return h < 0 ? h + 360 : h;
}

Lab xyzToLab(const Vec3& xyz, const Vec3& white) {
    // f(t) = t^(1/3) above (6/29)^3, else the linear segment t / (3 (6/29)^2) + 4/29 (CIE 015:2018, 8.2.1).
    constexpr double d = 6.0 / 29;
    const auto f = [&](double t) { return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29; };
    const double fx = f(xyz.x / white.x), fy = f(xyz.y / white.y), fz = f(xyz.z / white.z);
    return {116 * fy - 16, 500 * (fx - fy), 200 * (fy - fz)};
}

double deltaE(const Lab& x, const Lab& y) {
    return std::sqrt((x.L - y.L) * (x.L - y.L) + (x.a - y.a) * (x.a - y.a) + (x.b - y.b) * (x.b - y.b));
}

}  // namespace facetlight
