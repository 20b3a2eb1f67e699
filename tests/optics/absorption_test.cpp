// Absorption spectra: interpolation, and a job's table refused with the field at fault named.
#include "optics/absorption.h"

#include <gtest/gtest.h>

#include <cmath>

#include "colour/cie.h"
#include "optics/transmission_colour.h"
#include "study/job_request.h"
#include "support/expect_error.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;

TEST(AbsorptionSpectrum, LinearBetweenPointsAndFlatBeyond) {
    const AbsorptionSpectrum a{{400, 500, 700}, {1, 3, 0}, {2, 2, 4}};
    EXPECT_DOUBLE_EQ(a.ordinary(450), 2);
    EXPECT_DOUBLE_EQ(a.ordinary(600), 1.5);
    EXPECT_DOUBLE_EQ(a.ordinary(300), 1);
    EXPECT_DOUBLE_EQ(a.ordinary(800), 0);
    EXPECT_DOUBLE_EQ(a.extraordinary(650), 3.5);
    EXPECT_TRUE(a.absorbs());
    const AbsorptionSpectrum isotropic{{400, 700}, {0.5, 1.5}, {}};
    EXPECT_DOUBLE_EQ(isotropic.extraordinary(550), 1);  // as ordinary
    EXPECT_FALSE((AbsorptionSpectrum{{400, 700}, {0, 0}, {0, 0}}.absorbs()));
}

TEST(AbsorptionSpectrum, ExtraordinaryWaveMixesByTheAngleToTheAxis) {
    EXPECT_DOUBLE_EQ(extraordinaryAbsorption(1, 3, 1), 1);    // along the axis: ordinary
    EXPECT_DOUBLE_EQ(extraordinaryAbsorption(1, 3, 0), 3);    // across it: alpha_e
    EXPECT_DOUBLE_EQ(extraordinaryAbsorption(1, 3, 0.5), 2);  // 45 deg
}

std::string errorField(const json& absorption, const std::string& material = "sapphire") {
    return test::refusedField([&] {
        JobRequest::fromJson(
            {{"mesh", "round_brilliant"}, {"material", material}, {"absorption", absorption}});
    });
}

TEST(AbsorptionSpectrum, ABadTableNamesTheFieldAtFault) {
    const json good = {{"wavelength_nm", {400, 700}}, {"ordinary_per_mm", {0.1, 0.2}}};
    EXPECT_EQ(errorField(good), "no error");
    EXPECT_EQ(errorField(nullptr), "no error");
    json j = good;
    j["extraordinary_per_mm"] = {0.3, 0.4};
    EXPECT_EQ(errorField(j), "no error");
    EXPECT_EQ(errorField(j, "diamond"), "absorption.extraordinary_per_mm");  // isotropic: one spectrum
    EXPECT_EQ(errorField(5), "absorption");
    EXPECT_EQ(errorField(json::array()), "absorption");
    EXPECT_EQ(errorField({{"wavelength_nm", {400, 700}}}), "absorption.ordinary_per_mm");
    EXPECT_EQ(errorField({{"wavelength_nm", {400, 700}}, {"ordinary_per_mm", {0.1, 0.2}}, {"colour", 1}}),
              "absorption.colour");
    EXPECT_EQ(errorField({{"wavelength_nm", {700, 400}}, {"ordinary_per_mm", {0.1, 0.2}}}),
              "absorption.wavelength_nm[1]");  // unsorted
    EXPECT_EQ(errorField({{"wavelength_nm", {500, 500}}, {"ordinary_per_mm", {0.1, 0.2}}}),
              "absorption.wavelength_nm[1]");  // repeated
    EXPECT_EQ(errorField({{"wavelength_nm", {-400, 700}}, {"ordinary_per_mm", {0.1, 0.2}}}),
              "absorption.wavelength_nm[0]");  // negative
    EXPECT_EQ(errorField({{"wavelength_nm", {400, 700}}, {"ordinary_per_mm", {0.1, -0.2}}}),
              "absorption.ordinary_per_mm[1]");  // negative coefficient
    EXPECT_EQ(errorField({{"wavelength_nm", {400, 700}}, {"ordinary_per_mm", {0.1, "x"}}}),
              "absorption.ordinary_per_mm[1]");
    EXPECT_EQ(errorField({{"wavelength_nm", {400}}, {"ordinary_per_mm", {0.1}}}),
              "absorption.wavelength_nm");  // too few
    EXPECT_EQ(errorField({{"wavelength_nm", {400, 500, 700}}, {"ordinary_per_mm", {0.1, 0.2}}}),
              "absorption.ordinary_per_mm");  // one short
    json many = {{"wavelength_nm", json::array()}, {"ordinary_per_mm", json::array()}};
    for (size_t i = 0; i <= AbsorptionSpectrum::kMaxPoints; ++i) {
        many["wavelength_nm"].push_back(300 + 0.1 * double(i));
        many["ordinary_per_mm"].push_back(0.1);
    }
    EXPECT_EQ(errorField(many), "absorption.wavelength_nm");  // too many
    j = good;
    j["extraordinary_per_mm"] = {0.3, -1};
    EXPECT_EQ(errorField(j), "absorption.extraordinary_per_mm[1]");
}

TEST(AbsorptionSpectrum, JsonRoundTrip) {
    const json j = {{"wavelength_nm", {400, 550.5, 700}},
                    {"ordinary_per_mm", {0.1, 0, 2}},
                    {"extraordinary_per_mm", {0.3, 0.4, 0}}};
    const AbsorptionSpectrum a = readAbsorption(j, "absorption");
    EXPECT_EQ(toJson(a), j);
    const JobRequest job =
        JobRequest::fromJson({{"mesh", "m"}, {"material", "tourmaline"}, {"absorption", j}});
    ASSERT_TRUE(job.settings.trace.absorption);
    EXPECT_EQ(*job.settings.trace.absorption, a);
    EXPECT_EQ(toJson(job)["absorption"], j);
}

// A biaxial material's rays: read and written back, refused by name when one is missing, beside the o/e
// columns or on a material that is not biaxial; their mean is the one spectrum.
TEST(AbsorptionSpectrum, ABiaxialMaterialsRays) {
    const json rays = {{"wavelength_nm", {400, 700}},
                       {"x_per_mm", {0.3, 0.0}},
                       {"y_per_mm", {0.6, 0.3}},
                       {"z_per_mm", {0.0, 0.9}}};
    const AbsorptionSpectrum a = readAbsorption(rays, "absorption");
    ASSERT_TRUE(a.trichroic());
    EXPECT_EQ(toJson(a), rays);
    EXPECT_DOUBLE_EQ(a.ordinary(400), 0.3);
    EXPECT_DOUBLE_EQ(a.ordinary(700), 0.4);
    EXPECT_DOUBLE_EQ(a.ray(2, 550), 0.45);
    EXPECT_EQ(errorField(rays, "peridot"), "no error");
    EXPECT_EQ(errorField(rays, "sapphire"), "absorption.x_per_mm");  // uniaxial
    EXPECT_EQ(errorField(rays, "diamond"), "absorption.x_per_mm");   // isotropic
    json j = rays;
    j.erase("y_per_mm");
    EXPECT_EQ(errorField(j, "peridot"), "absorption.y_per_mm");
    j = rays;
    j["ordinary_per_mm"] = {0.1, 0.1};
    EXPECT_EQ(errorField(j, "peridot"), "absorption.ordinary_per_mm");
    j = rays;
    j["z_per_mm"] = {0.1, 0.1, 0.1};
    EXPECT_EQ(errorField(j, "peridot"), "absorption.z_per_mm");
}

// What `mm` of a spectrum transmits of D65, against D65's white: the tracer's own interpolation of the table
// (linear between its 10 nm points), summed at the CIE tables' 5 nm rows, independent of the fit's sigmoid.
Lab transmittedThrough(const AbsorptionSpectrum& s, double mm) {
    return xyzToLab(tristimulus(Illuminant::D65, [&](double nm) { return std::exp(-s.ordinary(nm) * mm); }),
                    whitePoint(Illuminant::D65));
}

// A colour by transmission gives the spectrum that transmits that colour through its path: traced back
// through the table, each comes out within 0.3 Delta E (the table's 10 nm steps against the fit's smooth
// curve).
TEST(ColourByTransmission, TheSpectrumTransmitsTheColourAsked) {
    const std::vector<Lab> targets = {{70, -5, -30}, {85, 12, -6}, {60, -40, 20}, {35, 45, 25}, {92, 0, 25}};
    for (const Lab& target : targets) {
        SCOPED_TRACE(testing::Message() << target.L << " " << target.a << " " << target.b);
        const AbsorptionSpectrum s = readAbsorption(
            json{{"transmitted_colour", {target.L, target.a, target.b}}, {"path_mm", 2}}, "absorption");
        EXPECT_EQ(s.wavelengthNm, kTransmissionWavelengthsNm);
        EXPECT_LT(deltaE(transmittedThrough(s, 2), target), 0.3);
        EXPECT_TRUE(s.extraordinaryPerMm.empty());
        // Through twice the path the same stone is darker: the single-pass transmission squared.
        EXPECT_LT(transmittedThrough(s, 4).L, target.L);
    }
}

// A neutral grey is transmitted by a flat spectrum: every coefficient within 1 % of their mean.
TEST(ColourByTransmission, GreyIsAFlatSpectrum) {
    const AbsorptionSpectrum s = readAbsorption(json{{"transmitted_colour", {60, 0, 0}}}, "absorption");
    double mean = 0;
    for (const double a : s.ordinaryPerMm) mean += a / double(s.ordinaryPerMm.size());
    EXPECT_GT(mean, 0.1);
    for (const double a : s.ordinaryPerMm) EXPECT_NEAR(a, mean, 0.01 * mean);
}

// The path only scales the coefficients: twice the path, half the alpha, for the same transmitted colour.
TEST(ColourByTransmission, ThePathScalesTheCoefficients) {
    const json colour = {56, 20, -25};
    const AbsorptionSpectrum one = readAbsorption(json{{"transmitted_colour", colour}}, "absorption");
    const AbsorptionSpectrum two =
        readAbsorption(json{{"transmitted_colour", colour}, {"path_mm", 2}}, "absorption");
    for (size_t i = 0; i < one.ordinaryPerMm.size(); ++i)
        EXPECT_DOUBLE_EQ(two.ordinaryPerMm[i] * 2, one.ordinaryPerMm[i]);
}

// sRGB's mid grey #808080 is L* 53.585 (IEC 61966-2-1's decoding, 128/255 -> 0.2158605 linear, Y^(1/3) by
// CIE 015); white is L* 100 with no hue.
TEST(ColourByTransmission, SrgbHexIsDecodedAsTheStandardSays) {
    const Lab grey = srgbHexToLab("#808080", "c");
    EXPECT_NEAR(grey.L, 53.585, 0.001);
    EXPECT_NEAR(grey.a, 0, 1e-4);
    EXPECT_NEAR(grey.b, 0, 1e-4);
    const Lab white = srgbHexToLab("#FFFFFF", "c");
    EXPECT_NEAR(white.L, 100, 1e-9);
    const AbsorptionSpectrum blue = readAbsorption(json{{"transmitted_colour", "#5b8fd0"}}, "absorption");
    EXPECT_LT(deltaE(transmittedThrough(blue, 1), srgbHexToLab("#5b8fd0", "c")), 0.3);
    // Pleochroic: each wave its own colour.
    const AbsorptionSpectrum two = readAbsorption(
        json{{"transmitted_colour", "#5b8fd0"}, {"extraordinary_transmitted_colour", "#9fc79a"}},
        "absorption");
    EXPECT_EQ(two.extraordinaryPerMm.size(), two.ordinaryPerMm.size());
    EXPECT_NE(two.extraordinaryPerMm, two.ordinaryPerMm);
}

TEST(ColourByTransmission, AColourNoFilterShowsIsRefused) {
    EXPECT_EQ(errorField({{"transmitted_colour", {95, 80, 0}}}), "absorption.transmitted_colour");
    EXPECT_EQ(errorField({{"transmitted_colour", "#12345"}}), "absorption.transmitted_colour");
    EXPECT_EQ(errorField({{"transmitted_colour", "#12345g"}}), "absorption.transmitted_colour");
    EXPECT_EQ(errorField({{"transmitted_colour", "#+f+f+f"}}), "absorption.transmitted_colour");
    EXPECT_EQ(errorField({{"transmitted_colour", "#000000"}}), "absorption.transmitted_colour");  // L* 0
    EXPECT_EQ(errorField({{"transmitted_colour", {50, 0}}}), "absorption.transmitted_colour");
    EXPECT_EQ(errorField({{"transmitted_colour", {0, 0, 0}}}), "absorption.transmitted_colour");
    EXPECT_EQ(errorField({{"transmitted_colour", "#808080"}, {"path_mm", 0}}), "absorption.path_mm");
    EXPECT_EQ(errorField({{"transmitted_colour", "#808080"}, {"wavelength_nm", {400, 700}}}),
              "absorption.wavelength_nm");
    EXPECT_EQ(errorField({{"transmitted_colour", "#808080"}, {"extraordinary_transmitted_colour", "#9fc79a"}},
                         "diamond"),
              "absorption.extraordinary_per_mm");
}

}  // namespace
}  // namespace facetlight
