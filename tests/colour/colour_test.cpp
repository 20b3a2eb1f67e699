// The colour science (colour/cie.h, colour/colour_space.h) against the CIE's tables by hand: the white points
// of D65 and A, a monochromatic light's tristimulus values against its row of the colour matching functions,
// a grey is neutral, the sRGB primaries and transfer curve, CIELAB's white and its linear segment.
#include <gtest/gtest.h>

#include <cmath>

#include "colour/cie.h"
#include "colour/colour_space.h"

namespace facetlight {
namespace {

void expectNear(const Vec3& got, const Vec3& want, double tolerance) {
    EXPECT_NEAR(got.x, want.x, tolerance);
    EXPECT_NEAR(got.y, want.y, tolerance);
    EXPECT_NEAR(got.z, want.z, tolerance);
}

TEST(Cie, WhitePointsAreTheCiesToTheTablesRounding) {
    // CIE 015:2018 table 11.3 (5 nm sums): D65 (95.04, 100, 108.88), A (109.85, 100, 35.58); the sRGB
    // standard's D65 (0.9505, 1, 1.089).
    expectNear(whitePoint(Illuminant::D65), {0.9504, 1, 1.0888}, 1.5e-4);
    expectNear(whitePoint(Illuminant::A), {1.0985, 1, 0.3558}, 1.5e-4);
}

TEST(Cie, TheTablesRowsAreTheCurve) {
    // The curve passes through the CIE's rows: 550 nm and 600 nm as tabulated.
    expectNear(cieXyz(550), {0.4334499, 0.9949501, 0.008749999}, 1e-12);
    expectNear(cieXyz(600), {1.0622, 0.631, 0.0008}, 1e-12);
    EXPECT_EQ(cieXyz(379.9), Vec3{});
    EXPECT_DOUBLE_EQ(illuminantPower(Illuminant::D65, 560), 100);
    EXPECT_NEAR(illuminantPower(Illuminant::A, 560), 100, 1e-12);
    EXPECT_NEAR(illuminantPower(Illuminant::D65, 382.5), (49.9755 + 52.3118) / 2, 1e-12);
}

TEST(Cie, MonochromaticLightHasItsRowsChromaticity) {
    // Only the 550 nm row passes: XYZ is that row times S(550) / sum S y-bar.
    const Vec3 xyz = tristimulus(Illuminant::D65, [](double l) { return std::abs(l - 550) < 1 ? 1.0 : 0.0; });
    const double x = 0.4334499, y = 0.9949501, z = 0.008749999;
    // By hand from the two tables (a spreadsheet's SUMPRODUCT of their columns): sum S(l) y-bar(l) =
    // 2113.455.
    double k = 0;
    for (double l = 380; l <= 780; l += 5) k += illuminantPower(Illuminant::D65, l) * cieXyz(l).y;
    EXPECT_NEAR(k, 2113.455, 1e-3);
    expectNear(xyz, Vec3{x, y, z} * (104.046 / k), 1e-12);
    EXPECT_NEAR(xyz.x / (xyz.x + xyz.y + xyz.z), 0.30160, 5e-5);  // the spectral locus at 550 nm
    EXPECT_NEAR(xyz.y / (xyz.x + xyz.y + xyz.z), 0.69231, 5e-5);
}

TEST(Cie, AGreyIsNeutral) {
    for (Illuminant illuminant : {Illuminant::D65, Illuminant::A}) {
        const Vec3 white = whitePoint(illuminant);
        const Lab grey = xyzToLab(tristimulus(illuminant, [](double) { return 0.18; }), white);
        EXPECT_NEAR(grey.L, 116 * std::cbrt(0.18) - 16, 1e-9);
        EXPECT_NEAR(grey.a, 0, 1e-9);
        EXPECT_NEAR(grey.b, 0, 1e-9);
    }
    // Under D65 the white is sRGB's white.
    const Vec3 rgb = xyzToLinearSrgb(whitePoint(Illuminant::D65));
    expectNear(rgb, {1, 1, 1}, 2e-3);
}

TEST(ColourSpace, SrgbPrimariesAndTransferCurve) {
    // IEC 61966-2-1: the red primary at x 0.64, y 0.33 with Y 0.2126 is linear (1, 0, 0).
    const double Y = 0.2126, x = 0.64, y = 0.33;
    expectNear(xyzToLinearSrgb({x / y * Y, Y, (1 - x - y) / y * Y}), {1, 0, 0}, 1e-3);
    EXPECT_NEAR(srgbEncode(0.5), 1.055 * std::pow(0.5, 1 / 2.4) - 0.055, 1e-15);
    EXPECT_NEAR(srgbEncode(0.002), 12.92 * 0.002, 1e-15);
    EXPECT_NEAR(srgbEncode(2), 1, 1e-15);  // clamped
}

TEST(ColourSpace, LabOfWhiteAndOfTheDarkSegment) {
    const Vec3 white = whitePoint(Illuminant::D65);
    const Lab w = xyzToLab(white, white);
    EXPECT_NEAR(w.L, 100, 1e-12);
    EXPECT_NEAR(w.chroma(), 0, 1e-12);
    // Below (6/29)^3 L* is 903.3 Y (CIE 015:2018, 8.2.1).
    EXPECT_NEAR(xyzToLab(white * 0.005, white).L, 24389.0 / 27 * 0.005, 1e-9);
    // A yellow: b* positive, hue near 90 deg.
    const Lab yellow =
        xyzToLab(tristimulus(Illuminant::D65, [](double l) { return l > 500 ? 1.0 : 0.0; }), white);
    EXPECT_GT(yellow.b, 50);
    EXPECT_NEAR(yellow.hueDeg(), 95, 15);
}

}  // namespace
}  // namespace facetlight
