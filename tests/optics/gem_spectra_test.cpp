#include "optics/gem_spectra.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "colour/cie.h"
#include "colour/colour_space.h"
#include "optics/material.h"
#include "scene/scene.h"
#include "support/fixtures.h"

namespace facetlight {
namespace {

const std::vector<std::string> kColoured = {"ruby",    "blue_sapphire", "emerald", "amethyst",
                                            "peridot", "alexandrite",   "zoisite"};

// CIELAB of what `mm` of the material passes of `illuminant`, against that illuminant's white: the
// unpolarised mixture 2/3 alpha_o + 1/3 alpha_e (docs/optics.md, "Absorption"), no surface reflection.
Lab transmitted(const Material& m, double mm, Illuminant illuminant = Illuminant::D65) {
    const AbsorptionSpectrum& s = *m.absorption();
    const auto tau = [&](double nm) {
        return std::exp(-(2 * s.ordinary(nm) + s.extraordinary(nm)) / 3 * mm);
    };
    return xyzToLab(tristimulus(illuminant, tau), whitePoint(illuminant));
}

TEST(GemSpectra, EachColouredMaterialShipsAValidSpectrum) {
    for (const std::string& name : kColoured) {
        SCOPED_TRACE(name);
        const Material m = Material::byName(name);
        ASSERT_TRUE(m.absorption());
        const AbsorptionSpectrum& s = *m.absorption();
        // readAbsorption checks what a job's table must be: strictly increasing wavelengths, one coefficient
        // per wavelength, each from 0 to 1e6 per mm.
        EXPECT_EQ(readAbsorption(toJson(s), "absorption"), s);
        EXPECT_TRUE(s.absorbs());
        // Zoisite's file starts at 401 nm: held at its 410 nm value below (docs/optics.md).
        EXPECT_LE(s.wavelengthNm.front(), name == "zoisite" ? 410 : 380);
        EXPECT_GE(s.wavelengthNm.back(), 780);
        if (!s.extraordinaryPerMm.empty()) {
            EXPECT_EQ(m.optic(), Optic::Uniaxial);
        }
        ASSERT_TRUE(m.densityGcm3());
    }
}

TEST(GemSpectra, ClearMaterialsStayClear) {
    for (const std::string& name : materialNames()) {
        const bool coloured = std::find(kColoured.begin(), kColoured.end(), name) != kColoured.end();
        EXPECT_EQ(Material::byName(name).absorption().has_value(), coloured) << name;
    }
}

// The hue family a gemmologist names, under D65 through 1 mm and through a 1-carat round's 6.5 mm.
TEST(GemSpectra, ColoursFallInTheirHueFamilies) {
    for (const double mm : {1.0, 6.5}) {
        SCOPED_TRACE(mm);
        const Lab ruby = transmitted(Material::byName("ruby"), mm);
        EXPECT_GT(ruby.a, 10);  // red: a* well above 0, above |b*|
        EXPECT_GT(ruby.a, std::abs(ruby.b));
        const Lab sapphire = transmitted(Material::byName("blue_sapphire"), mm);
        EXPECT_LT(sapphire.b, -5);  // blue
        const Lab emerald = transmitted(Material::byName("emerald"), mm);
        EXPECT_LT(emerald.a, -10);  // green
        const Lab amethyst = transmitted(Material::byName("amethyst"), mm);
        EXPECT_GT(amethyst.a, 0);  // purple: red and blue
        EXPECT_LT(amethyst.b, 0);
        const Lab peridot = transmitted(Material::byName("peridot"), mm);
        EXPECT_LT(peridot.a, 0);  // yellowish green
        EXPECT_GT(peridot.b, 0);
        const Lab alexandrite = transmitted(Material::byName("alexandrite"), mm);
        EXPECT_LT(alexandrite.a, 0);  // green in daylight
        // Darker through the longer path.
        if (mm > 1) {
            for (const std::string& name : kColoured)
                EXPECT_LT(transmitted(Material::byName(name), mm).L, transmitted(Material::byName(name), 1).L)
                    << name;
        }
    }
}

// Zoisite's trichroism, each ray through a 1-carat round's 6.5 mm: X (E || b) red-violet, Y (E || c) blue,
// Z (E || a) yellow-green, the colours gemmologists list for unheated tanzanite (O'Donoghue, Gems: red, blue and green
// or gold by direction); their mean, the one spectrum, is near grey.
TEST(GemSpectra, ZoisiteShowsThreeColours) {
    const AbsorptionSpectrum s = *gemSpectrum("zoisite");
    ASSERT_TRUE(s.trichroic());
    const auto ray = [&](int axis) {
        return xyzToLab(
            tristimulus(Illuminant::D65, [&](double nm) { return std::exp(-s.ray(axis, nm) * 6.5); }),
            whitePoint(Illuminant::D65));
    };
    const Lab x = ray(0), y = ray(1), z = ray(2);
    EXPECT_GT(x.a, 3);
    EXPECT_LT(x.b, -3);
    EXPECT_LT(y.b, -3);
    EXPECT_LT(z.a, -3);
    EXPECT_GT(z.b, 3);
    EXPECT_LT(transmitted(Material::byName("zoisite"), 6.5).chroma(),
              std::min({x.chroma(), y.chroma(), z.chroma()}));
    // docs/optics.md's row, rounded: X 62 23 -16, Y 89 -3.5 -12, Z 92 -25 28 at 6.5 mm; the mean 97 0 0
    // through 1 mm and 80 -1 0 through 6.5 mm (near grey).
    const auto expectLab = [](const Lab& c, double L, double a, double b, const char* what) {
        EXPECT_NEAR(c.L, L, 0.6) << what;
        EXPECT_NEAR(c.a, a, 0.6) << what;
        EXPECT_NEAR(c.b, b, 0.6) << what;
    };
    expectLab(x, 62, 23, -16, "X");
    expectLab(y, 89, -3.5, -12, "Y");
    expectLab(z, 92, -25, 28, "Z");
    expectLab(transmitted(Material::byName("zoisite"), 1), 97, 0, 0, "mean, 1 mm");
    expectLab(transmitted(Material::byName("zoisite"), 6.5), 80, -1, 0, "mean, 6.5 mm");
}

// Alexandrite's colour change: redder under incandescent light (A) than in daylight (D65), each against its
// own white.
TEST(GemSpectra, AlexandriteTurnsRedderUnderIncandescentLight) {
    const Material m = Material::byName("alexandrite");
    EXPECT_GT(transmitted(m, 6.5, Illuminant::A).a, transmitted(m, 6.5).a + 5);
}

TEST(GemSpectra, AJobsTableReplacesTheMaterialsOwn) {
    SceneSettings settings;
    settings.material = "ruby";
    EXPECT_EQ(chooseMaterial(settings, test::roundBrilliant()).material.absorption(), gemSpectrum("ruby"));
    settings.absorption =
        AbsorptionSpectrum{.wavelengthNm = {400, 700}, .ordinaryPerMm = {0.1, 0.1}, .extraordinaryPerMm = {}};
    EXPECT_EQ(chooseMaterial(settings, test::roundBrilliant()).material.absorption(), settings.absorption);
}

// Peridot keeps its three rays (olivine GRR 418's alpha, beta and gamma files) as well as their mean, which
// is what it traced with before: the mean is the rays' mean bit for bit, and the table read back from its JSON
// (as a job would give it) equals the shipped one.
TEST(GemSpectra, PeridotKeepsItsRays) {
    const std::optional<AbsorptionSpectrum> peridot = gemSpectrum("peridot");
    ASSERT_TRUE(peridot && peridot->trichroic());
    EXPECT_EQ(AbsorptionSpectrum::meanOfRays(peridot->rayPerMm), peridot->ordinaryPerMm);
    EXPECT_EQ(readAbsorption(toJson(*peridot), "absorption"), *peridot);
    // Each ray is its own file: at 380 nm the beta ray absorbs most per mm (A 0.330 through 1.138 mm, against
    // 0.249 through 1.141 mm and 0.148 through 0.66 mm).
    EXPECT_GT(peridot->ray(1, 380), peridot->ray(0, 380));
    EXPECT_GT(peridot->ray(1, 380), peridot->ray(2, 380));
    // Alexandrite lacks its alpha ray: one spectrum.
    EXPECT_FALSE(gemSpectrum("alexandrite")->trichroic());
}

}  // namespace
}  // namespace facetlight
