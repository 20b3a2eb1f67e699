#include "optics/material.h"

#include <gtest/gtest.h>

#include <cmath>

#include "util/error.h"

namespace facetlight {
namespace {

struct Expected {
    const char* name;
    double nD;
    double dispersion;
};

// n_D and B-G as tabulated in docs/optics.md (rounded there to the digits shown).
class MaterialTable : public testing::TestWithParam<Expected> {};

TEST_P(MaterialTable, MatchesTabulatedIndexAndDispersion) {
    const Expected& e = GetParam();
    const Material m = Material::byName(e.name);
    EXPECT_EQ(m.name(), e.name);
    EXPECT_NEAR(m.indexD(), e.nD, 6e-4);
    EXPECT_NEAR(m.dispersionBG(), e.dispersion, 6e-4);
    EXPECT_TRUE(m.dispersive());
    // Normal dispersion: the index falls with wavelength across the visible.
    EXPECT_GT(m.index(380), m.index(589.3));
    EXPECT_GT(m.index(589.3), m.index(780));
}

INSTANTIATE_TEST_SUITE_P(DocsOptics, MaterialTable,
                         testing::Values(Expected{"diamond", 2.4173, 0.044},
                                         Expected{"cubic_zirconia", 2.1585, 0.060},
                                         Expected{"sapphire", 1.768, 0.018},
                                         Expected{"fused_silica", 1.4584, 0.0115},
                                         Expected{"bk7", 1.5168, 0.0138}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Material, DiamondNormalReflectance) {
    const double n = Material::byName("diamond").indexD();
    EXPECT_NEAR((n - 1) * (n - 1) / ((n + 1) * (n + 1)), 0.1720, 1e-4);
}

TEST(Material, ConstantIndexIgnoresWavelength) {
    const Material m = Material::constant(2.0);
    EXPECT_FALSE(m.dispersive());
    EXPECT_EQ(m.index(400), 2.0);
    EXPECT_EQ(m.index(700), 2.0);
    EXPECT_EQ(m.dispersionBG(), 0.0);
}

TEST(Material, RejectsUnknownNamesAndBadIndices) {
    EXPECT_THROW(Material::byName("moissanite"), Error);
    EXPECT_THROW(Material::constant(1.0), Error);
    EXPECT_THROW(Material::constant(NAN), Error);
    try {
        Material::byName("glass");
        FAIL();
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("diamond"), std::string::npos) << "lists the known names";
    }
    EXPECT_EQ(materialNames().size(), 5u);
}

}  // namespace
}  // namespace facetlight
