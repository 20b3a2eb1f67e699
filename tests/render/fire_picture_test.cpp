// The fire picture: its colour pipeline against the CIE and sRGB reference values, grey without dispersion
// and coloured with diamond's, the same bytes at any thread count, a PNG of the render's size, and its place
// among a study's results.
#include "render/fire_picture.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

#include "colour/colour_space.h"
#include "image/image.h"
#include "optics/spectrum.h"
#include "scene/scene.h"
#include "study/result_files.h"
#include "study/study.h"
#include "support/fixtures.h"
#include "util/error.h"

namespace facetlight {
namespace {

using test::roundBrilliant;

struct Decoded {
    int width = 0, height = 0;
    std::vector<unsigned char> rgb;  // 3 bytes a pixel
};

Decoded decodePng(const std::string& png) {
    Decoded d;
    int channels = 0;
    const std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()), int(png.size()), &d.width,
                              &d.height, &channels, 3),
        stbi_image_free);
    EXPECT_NE(pixels, nullptr) << "not a PNG";
    if (pixels) d.rgb.assign(pixels.get(), pixels.get() + size_t(d.width) * size_t(d.height) * 3);
    return d;
}

TraceSettings trace(bool dispersion, int threads = 2) {
    TraceSettings t;
    t.material = "diamond";
    t.dispersion = dispersion;
    t.threads = threads;
    t.seed = 5;
    return t;
}

RenderSettings small() {
    RenderSettings r;
    r.width = 96;
    r.height = 80;
    return r;
}

FirePictureSettings fewWavelengths() {
    FirePictureSettings f;
    f.wavelengths = 12;
    return f;
}

std::string firePng(const TraceSettings& t, const FirePictureSettings& f = fewWavelengths()) {
    const Scene scene(roundBrilliant(), t);
    return encodePng(toDisplay(firePicture(scene, small(), f, t.threads, t.seed)));
}

// XYZ of an equal-energy spectrum over [lo, hi] nm, 1 nm midpoint steps.
Vec3 flatXyz(double lo, double hi) {
    Vec3 sum;
    for (double l = lo + 0.5; l < hi; l += 1) sum += cieXyz(l);
    return sum;
}

// The multi-lobe Gaussian fit to the CIE 1931 functions (Wyman, Sloan & Shirley, "Simple Analytic
// Approximations to the CIE XYZ Color Matching Functions", JCGT 2(2), 2013, eq. 2 and table 1): an
// independent computation that the table's values must stay near (it is good to a few hundredths).
Vec3 wymanFit(double l) {
    const auto g = [l](double mean, double left, double right) {
        const double t = (l - mean) / (l < mean ? left : right);
        return std::exp(-0.5 * t * t);
    };
    return {1.056 * g(599.8, 37.9, 31.0) + 0.362 * g(442.0, 16.0, 26.7) - 0.065 * g(501.1, 20.4, 26.2),
            0.821 * g(568.8, 46.9, 40.5) + 0.286 * g(530.9, 16.3, 31.1),
            1.217 * g(437.0, 11.8, 36.0) + 0.681 * g(459.0, 26.0, 13.8)};
}

// The colour-matching functions the picture weights its wavelengths with: the CIE 1931 table sums y-bar over
// 360-830 nm at 1 nm to 106.857 (CIE 015:2004, table T.4; CVRL), and x-bar, y-bar, z-bar have equal areas
// (illuminant E is x = y = 1/3 by construction); at 700 nm the chromaticity is x 0.7347, y 0.2653.
TEST(FirePicture, ColourMatchingFunctionsAreTheCies) {
    const Vec3 all = flatXyz(360, 830);
    EXPECT_NEAR(all.y, 106.857, 0.002 * 106.857);
    EXPECT_NEAR(all.x / all.y, 1, 0.002);
    EXPECT_NEAR(all.z / all.y, 1, 0.003);
    const Vec3 red = cieXyz(700);
    EXPECT_NEAR(red.x / (red.x + red.y + red.z), 0.7347, 1e-3);
    EXPECT_NEAR(red.y / (red.x + red.y + red.z), 0.2653, 1e-3);
    for (double l = 380; l <= 780; l += 1) {
        const Vec3 table = cieXyz(l), fit = wymanFit(l);
        EXPECT_NEAR(table.x, fit.x, 0.05) << l;
        EXPECT_NEAR(table.y, fit.y, 0.05) << l;
        EXPECT_NEAR(table.z, fit.z, 0.08) << l;
    }
    // The traced range 380-730 nm keeps all but a few parts in a thousand of it.
    const Vec3 traced = flatXyz(kFireMinWavelength, kFireMaxWavelength);
    EXPECT_NEAR(traced.y / all.y, 1, 0.003);
    EXPECT_NEAR(traced.x / all.x, 1, 0.003);
}

// IEC 61966-2-1: the D65 white (x 0.3127, y 0.3290, Y 1) is linear sRGB (1, 1, 1).
TEST(FirePicture, SrgbMatrixTakesD65ToWhite) {
    const double x = 0.3127, y = 0.3290;
    const Vec3 rgb = xyzToLinearSrgb({x / y, 1, (1 - x - y) / y});
    EXPECT_NEAR(rgb.x, 1, 2e-3);
    EXPECT_NEAR(rgb.y, 1, 2e-3);
    EXPECT_NEAR(rgb.z, 1, 2e-3);
}

// The white balance shows the light's flat spectrum as grey, and single wavelengths in their hue.
TEST(FirePicture, WhiteIsGreyAndSpectralLinesHaveTheirHue) {
    const Vec3 white = balancedSrgb(flatXyz(kFireMinWavelength, kFireMaxWavelength) * 0.25);
    EXPECT_NEAR(white.x / white.y, 1, 1e-3);
    EXPECT_NEAR(white.z / white.y, 1, 1e-3);
    const Vec3 red = balancedSrgb(cieXyz(700));
    EXPECT_GT(red.x, 0);
    EXPECT_GT(red.x, 10 * std::max(red.y, 0.0));
    EXPECT_GT(red.x, 10 * std::max(red.z, 0.0));
    const Vec3 green = balancedSrgb(cieXyz(530));
    EXPECT_GT(green.y, 3 * std::max({green.x, green.z, 0.0}));
    const Vec3 blue = balancedSrgb(cieXyz(450));
    EXPECT_GT(blue.z, 3 * std::max({blue.x, blue.y, 0.0}));
}

// The largest spread between a pixel's channels, and how many pixels are coloured (spread above 48 of 255).
struct Colourfulness {
    int maxSpread = 0, coloured = 0, lit = 0;
};

Colourfulness colourfulness(const Decoded& d) {
    Colourfulness c;
    for (size_t i = 0; i + 2 < d.rgb.size(); i += 3) {
        const auto [lo, hi] = std::minmax({d.rgb[i], d.rgb[i + 1], d.rgb[i + 2]});
        c.maxSpread = std::max(c.maxSpread, hi - lo);
        c.coloured += hi - lo > 48;
        c.lit += hi > 0;
    }
    return c;
}

// Without dispersion every wavelength takes the same path: the light's white comes out grey in every pixel
// (up to the last bit of rounding). With diamond's dispersion red and blue part, and the flashes are
// coloured.
TEST(FirePicture, GreyWithoutDispersionColouredWithDiamonds) {
    const Decoded grey = decodePng(firePng(trace(false)));
    ASSERT_EQ(grey.width, 96);
    ASSERT_EQ(grey.height, 80);
    const Colourfulness g = colourfulness(grey);
    EXPECT_LE(g.maxSpread, 1);
    EXPECT_GT(g.lit, 96 * 80 / 4) << "the stone and its outline show";

    const Decoded fire = decodePng(firePng(trace(true)));
    ASSERT_EQ(fire.width, 96);
    ASSERT_EQ(fire.height, 80);
    const Colourfulness f = colourfulness(fire);
    EXPECT_GT(f.maxSpread, 150);
    EXPECT_GT(f.coloured, 20) << "flashes of colour";
}

TEST(FirePicture, SameBytesAtAnyThreadCount) {
    const std::string one = firePng(trace(true, 1));
    EXPECT_EQ(one, firePng(trace(true, 2)));
    EXPECT_EQ(one, firePng(trace(true, 3)));
}

// A study with a render and a fire picture returns fire.png among its files; the settings are checked.
TEST(FirePicture, StudyWritesFirePng) {
    StudySettings s;
    s.trace = trace(true);
    s.trace.photons = 2000;
    s.render = small();
    s.render->mapPhotons = 2000;
    s.render->samples = 1;
    s.firePicture = fewWavelengths();
    RunControl control;
    const StudyResult result = runStudy(roundBrilliant(), s, control);
    const Decoded d = decodePng(result.file("fire.png"));
    EXPECT_EQ(d.width, 96);
    EXPECT_EQ(d.height, 80);
    const auto file = std::find_if(kResultFiles.begin(), kResultFiles.end(),
                                   [](const ResultFile& f) { return f.name == "fire.png"; });
    ASSERT_NE(file, kResultFiles.end());
    EXPECT_EQ(file->needs, "fire_picture");
    EXPECT_EQ(result.bytes(*file), result.file("fire.png"));

    s.render.reset();
    EXPECT_THROW(runStudy(roundBrilliant(), s, control), Error);
    const Scene scene(roundBrilliant(), trace(true));
    FirePictureSettings bad;
    bad.lightRadiusDeg = 0;
    EXPECT_THROW(firePicture(scene, small(), bad, 1, 1), Error);
}

}  // namespace
}  // namespace facetlight
