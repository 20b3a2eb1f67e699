// Absorption spectra: interpolation, and a job's table refused with the field at fault named.
#include "optics/absorption.h"

#include <gtest/gtest.h>

#include "study/job_request.h"
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
    try {
        JobRequest::fromJson(
            {{"mesh", "round_brilliant"}, {"material", material}, {"absorption", absorption}});
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos) << e.what();
        return e.field();
    }
    return "no error";
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

}  // namespace
}  // namespace facetlight
