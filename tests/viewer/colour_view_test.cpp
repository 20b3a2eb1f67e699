// The colour a viewer sees (viewer/colour_view.h): a clear stone under D65 is neutral, a grey absorber is
// neutral, a slab's colour is the illuminant through (1-R)^2 tau / (1 - R^2 tau^2) with tau = exp(-alpha L)
// computed here from the spectrum, doubling the size darkens an absorbing stone, and the view is the same
// bits at any thread count.
#include <gtest/gtest.h>

#include <cmath>

#include "pictures/colour_picture.h"
#include "pictures/face_up_frame.h"
#include "support/fixtures.h"
#include "util/error.h"
#include "viewer/colour_view.h"

namespace facetlight {
namespace {

TraceSettings settingsOf(std::optional<AbsorptionSpectrum> absorption, double sizeMm = 6.5) {
    TraceSettings s;
    s.seed = 5;
    s.threads = 2;
    s.absorption = std::move(absorption);
    s.sizeMm = sizeMm;
    return s;
}

ColourSettings small() {
    ColourSettings c;
    c.pictureSize = 48;
    return c;
}

// A blue-green test spectrum: clear in the blue, absorbing toward the red (an illustration, not a gem's).
AbsorptionSpectrum blueGreen() {
    return {{380, 500, 600, 700, 780}, {0.02, 0.05, 0.3, 0.6, 0.6}, {}};
}

TEST(ColourView, AClearStoneUnderD65IsNeutral) {
    const ColourView v = colourView(test::roundBrilliant(), settingsOf(std::nullopt), small());
    ASSERT_GT(v.pixels, 1000u);
    EXPECT_FALSE(v.absorbs);
    // Dispersion colours single pixels; their mean over the face is white light again.
    EXPECT_NEAR(v.meanLab.a, 0, 1.5);
    EXPECT_NEAR(v.meanLab.b, 0, 1.5);
    EXPECT_NEAR(v.a.mean, 0, 4 * v.a.meanError + 0.5);
    EXPECT_NEAR(v.b.mean, 0, 4 * v.b.meanError + 0.5);
    EXPECT_GT(v.meanLab.L, 40);
}

TEST(ColourView, AGreyAbsorberIsNeutral) {
    TraceSettings s = settingsOf(AbsorptionSpectrum{{380, 780}, {0.3, 0.3}, {}});
    s.dispersion = false;  // every wavelength walks alike: the spectrum each pixel receives is flat
    const ColourView v = colourView(test::roundBrilliant(), s, small());
    EXPECT_TRUE(v.absorbs);
    EXPECT_NEAR(v.meanLab.a, 0, 1.0);
    EXPECT_NEAR(v.meanLab.b, 0, 1.0);
}

TEST(ColourView, ASlabTransmitsTheIlluminantThroughBeerLambert) {
    const Stone cube = test::unitCube();
    TraceSettings s = settingsOf(blueGreen());
    s.dispersion = false;
    ColourSettings c = small();
    c.samples = 8;
    const ColourView v = colourView(cube, s, c);
    ASSERT_GT(v.pixels, 1500u);
    // Straight down through the top: reflections go back up into the dark head cone, what crosses the slab
    // sees the white ground, so the slab passes (1-R)^2 tau / (1 - R^2 tau^2) of the dome's light.
    const double d = s.sizeMm / Scene(cube, s).diameter();
    const double n = Scene(cube, s).fixedIndex(), R = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    const AbsorptionSpectrum a = blueGreen();
    auto alpha = [&](double l) {  // linear between the spectrum's points, written out again here
        for (size_t i = 0; i + 1 < a.wavelengthNm.size(); ++i)
            if (l <= a.wavelengthNm[i + 1]) {
                const double t = (l - a.wavelengthNm[i]) / (a.wavelengthNm[i + 1] - a.wavelengthNm[i]);
                return a.ordinaryPerMm[i] + t * (a.ordinaryPerMm[i + 1] - a.ordinaryPerMm[i]);
            }
        return a.ordinaryPerMm.back();
    };
    const Vec3 want = tristimulus(Illuminant::D65, [&](double l) {
        const double tau = std::exp(-alpha(l) * d);
        return (1 - R) * (1 - R) * tau / (1 - R * R * tau * tau);
    });
    // Each of X, Y, Z within 4 standard errors of its mean over the slab's pixels, and the 0.2 % by which
    // the view's integral differs from the table's 5 nm sum.
    for (int c = 0; c < 3; ++c) {
        double sum = 0, squares = 0;
        for (size_t k = 0; k < v.xyz.size(); ++k)
            if (v.onStone(k)) {
                sum += v.xyz[k][c];
                squares += v.xyz[k][c] * v.xyz[k][c];
            }
        const double m = double(v.pixels), mean = sum / m;
        const double se = std::sqrt((squares / m - mean * mean) / (m - 1));
        EXPECT_NEAR(v.meanXyz[c], want[c], 4 * se + 0.002 * want[c]) << "XYZ"[c];
        EXPECT_LT(se, 0.01 * want[c]);
    }
    const Lab lab = xyzToLab(want, v.white);
    EXPECT_NEAR(v.meanLab.L, lab.L, 0.5);
    EXPECT_NEAR(v.meanLab.a, lab.a, 0.5);
    EXPECT_NEAR(v.meanLab.b, lab.b, 0.5);
    EXPECT_LT(lab.a, -5);  // a blue-green, not a grey: the test has something to see
    // Without absorption's weight, the share of rays that cross is the clear slab's (1-R)/(1+R).
    EXPECT_NEAR(v.windowed.share, (1 - R) / (1 + R), 4 * v.windowed.standardError);
}

TEST(ColourView, DoublingTheSizeDarkensAnAbsorbingStone) {
    const ColourView small6 = colourView(test::roundBrilliant(), settingsOf(blueGreen(), 5), small());
    const ColourView large = colourView(test::roundBrilliant(), settingsOf(blueGreen(), 10), small());
    const double se = std::hypot(small6.L.meanError, large.L.meanError);
    EXPECT_LT(large.L.mean, small6.L.mean - 3 * se);
    EXPECT_LT(large.meanLab.L, small6.meanLab.L);
    EXPECT_GT(large.extinct.share, small6.extinct.share);
}

TEST(ColourView, TheSameBitsAtAnyThreadCount) {
    TraceSettings one = settingsOf(blueGreen()), four = one;
    one.threads = 1;
    four.threads = 4;
    ColourSettings c = small();
    c.pictureSize = 24;
    const ColourView a = colourView(test::roundBrilliant(), one, c),
                     b = colourView(test::roundBrilliant(), four, c);
    ASSERT_EQ(a.xyz.size(), b.xyz.size());
    for (size_t k = 0; k < a.xyz.size(); ++k) ASSERT_EQ(a.xyz[k], b.xyz[k]) << k;
    EXPECT_EQ(toJson(a), toJson(b));
}

TEST(ColourView, ThePictureHasItsTitleScaleAndLegend) {
    const ColourView v = colourView(test::roundBrilliant(), settingsOf(blueGreen()), small());
    const Image image = colourPicture(v, "title");
    EXPECT_GE(image.width(), 720);
    EXPECT_GT(image.height(), 480);
    // The figures above the view at the legible size (scale 2), in as many lines as they take.
    const TitleBlock head = titleBlock("title", colourSummary(v), image.width());
    EXPECT_GE(head.summary.size(), 3u);
    for (const std::string& line : head.summary) EXPECT_LE(textWidth(line, 2), image.width() - 10) << line;
    const nlohmann::json j = toJson(v);
    EXPECT_EQ(j["illuminant"], "D65");
    EXPECT_EQ(j["pixels"], v.pixels);
    EXPECT_TRUE(j["mean_colour"]["srgb"].get<std::string>().starts_with("#"));
}

TEST(ColourView, BadSettingsAreRefusedNamingTheField) {
    ColourSettings c = small();
    c.wavelengths = 2;
    try {
        colourView(test::roundBrilliant(), settingsOf(std::nullopt), c);
        FAIL() << "no error";
    } catch (const Error& e) {
        EXPECT_EQ(e.field(), "wavelengths");
    }
}

}  // namespace
}  // namespace facetlight
