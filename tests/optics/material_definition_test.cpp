#include "optics/material_definition.h"

#include <gtest/gtest.h>

#include <string>

#include "optics/material.h"
#include "scene/scene.h"
#include "support/fixtures.h"
#include "trace/photon_tracer.h"
#include "trace/trace_settings.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;

// The field a bad definition is refused for, or "" when it reads.
std::string refusedField(const json& j) {
    try {
        readMaterialDefinition(j, "custom_material");
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos) << "the message names the field";
        return e.field();
    }
    return "";
}

// The shipped tourmaline is Cauchy through GIA's 1.644 / 1.624 and 0.017 with SG 3.06 (docs/optics.md): the
// same numbers given as a job's own material make the same material, index for index.
TEST(MaterialDefinition, TheSameNumbersMakeTheShippedMaterial) {
    const Material defined = Material::defined(readMaterialDefinition(json{{"name", "my tourmaline"},
                                                                           {"n_o", 1.644},
                                                                           {"n_e", 1.624},
                                                                           {"dispersion", 0.017},
                                                                           {"density_g_cm3", 3.06}},
                                                                      "custom_material"));
    const Material shipped = Material::byName("tourmaline");
    EXPECT_EQ(defined.name(), "my tourmaline");
    EXPECT_EQ(defined.optic(), Optic::Uniaxial);
    EXPECT_EQ(defined.densityGcm3(), shipped.densityGcm3());
    for (const double nm : {380.0, 430.8, 589.3, 686.7, 780.0})
        EXPECT_EQ(defined.principalIndices(nm), shipped.principalIndices(nm)) << nm;
    EXPECT_TRUE(defined.dispersive());
}

TEST(MaterialDefinition, EachFormGivesItsOpticClass) {
    const Material glass = Material::defined(readMaterialDefinition(json{{"n", 1.52}}, "m"));
    EXPECT_EQ(glass.optic(), Optic::Isotropic);
    EXPECT_EQ(glass.name(), "custom");
    EXPECT_FALSE(glass.dispersive()) << "no dispersion given: one index at every wavelength";
    EXPECT_EQ(glass.index(400), 1.52);
    EXPECT_FALSE(glass.densityGcm3());
    const Material zoisite = Material::defined(readMaterialDefinition(
        json{{"alpha", 1.692}, {"beta", 1.693}, {"gamma", 1.700}, {"dispersion", 0.03}}, "m"));
    EXPECT_EQ(zoisite.optic(), Optic::Biaxial);
    EXPECT_NEAR(zoisite.indexD(), 1.693, 1e-12) << "traced at beta";
    EXPECT_NEAR(zoisite.dispersionBG(), 0.03, 1e-12);
    EXPECT_EQ(zoisite.opticSign(), 1);
}

TEST(MaterialDefinition, WritesWhatItRead) {
    const json j = {{"name", "spinel"}, {"n", 1.718}, {"dispersion", 0.02}, {"density_g_cm3", 3.6}};
    EXPECT_EQ(toJson(readMaterialDefinition(j, "m")), j);
}

TEST(MaterialDefinition, BadDefinitionsNameTheField) {
    EXPECT_EQ(refusedField(json{{"n", 1.5}}), "");
    EXPECT_EQ(refusedField(json::array({1.5})), "custom_material");
    EXPECT_EQ(refusedField(json::object()), "custom_material");
    EXPECT_EQ(refusedField(json{{"n", 1.5}, {"n_o", 1.6}, {"n_e", 1.7}}), "custom_material");
    EXPECT_EQ(refusedField(json{{"n_o", 1.6}}), "custom_material.n_e");
    EXPECT_EQ(refusedField(json{{"n_e", 1.6}}), "custom_material.n_o");
    EXPECT_EQ(refusedField(json{{"n_o", 1.6}, {"n_e", 1.6}}), "custom_material.n_e");
    EXPECT_EQ(refusedField(json{{"alpha", 1.6}, {"gamma", 1.7}}), "custom_material.beta");
    EXPECT_EQ(refusedField(json{{"alpha", 1.6}, {"beta", 1.75}, {"gamma", 1.7}}), "custom_material.beta");
    // Within 1e-7 its trace failed: both waves had one field.
    EXPECT_EQ(refusedField(json{{"alpha", 1.5}, {"beta", 1.500000001}, {"gamma", 1.500000002}}),
              "custom_material.gamma");
    EXPECT_EQ(refusedField(json{{"alpha", 1.5}, {"beta", 1.5000049}, {"gamma", 1.5000099}}),
              "custom_material.gamma");
    EXPECT_EQ(refusedField(json{{"alpha", 1.5}, {"beta", 1.50001}, {"gamma", 1.50002}}), "");
    EXPECT_EQ(refusedField(json{{"n", 1.0}}), "custom_material.n");
    EXPECT_EQ(refusedField(json{{"n", "1.5"}}), "custom_material.n");
    EXPECT_EQ(refusedField(json{{"n", 1.5}, {"dispersion", -0.01}}), "custom_material.dispersion");
    EXPECT_EQ(refusedField(json{{"n", 1.5}, {"density_g_cm3", 0}}), "custom_material.density_g_cm3");
    EXPECT_EQ(refusedField(json{{"n", 1.5}, {"name", ""}}), "custom_material.name");
    EXPECT_EQ(refusedField(json{{"n", 1.5}, {"index", 1.5}}), "custom_material.index");
    // n 1.1 with dispersion 0.56 would fall to 0.89 at 780 nm.
    EXPECT_EQ(refusedField(json{{"n", 1.1}, {"dispersion", 0.56}}), "custom_material.dispersion");
    EXPECT_EQ(refusedField(json{{"n", 1.1}, {"dispersion", 0.2}}), "");
}

TEST(MaterialDefinition, AJobGivesOneMaterialOnly) {
    const json material = {{"n_o", 1.644}, {"n_e", 1.624}};
    const auto refused = [](const json& job) -> std::string {
        try {
            TraceSettings::fromJson(job);
        } catch (const Error& e) {
            return e.field();
        }
        return "";
    };
    EXPECT_EQ(refused({{"custom_material", material}}), "");
    EXPECT_EQ(refused({{"custom_material", material}, {"material", "ruby"}}), "custom_material");
    EXPECT_EQ(refused({{"custom_material", material}, {"n", 1.6}}), "custom_material");
    // Its optic class decides what else it takes: an extraordinary spectrum needs a uniaxial material.
    const json pleochroic = {
        {"wavelength_nm", {400, 700}}, {"ordinary_per_mm", {0.1, 0.1}}, {"extraordinary_per_mm", {0.2, 0.2}}};
    EXPECT_EQ(refused({{"custom_material", material}, {"absorption", pleochroic}}), "");
    EXPECT_EQ(refused({{"custom_material", {{"n", 1.6}}}, {"absorption", pleochroic}}),
              "absorption.extraordinary_per_mm");
}

// Traced, the job's own tourmaline gives the shipped tourmaline's statistics bit for bit, and stats.json says
// where the material came from.
TEST(MaterialDefinition, TracesAsTheShippedMaterial) {
    TraceSettings shipped;
    shipped.photons = 20'000;
    shipped.material = "tourmaline";
    TraceSettings own = shipped;
    own.material = "auto";
    own.customMaterial = readMaterialDefinition(json{{"name", "tourmaline"},
                                                     {"n_o", 1.644},
                                                     {"n_e", 1.624},
                                                     {"dispersion", 0.017},
                                                     {"density_g_cm3", 3.06}},
                                                "custom_material");
    const Stone& stone = test::roundBrilliant();
    const TraceResult a = test::traceStone(stone, shipped), b = test::traceStone(stone, own);
    EXPECT_EQ(traceReport(a, stone, shipped).at("totals"), traceReport(b, stone, own).at("totals"));
    EXPECT_EQ(chooseMaterial(own, stone).source, "custom_material");
    // Messages and the sweep's pictures name it before a stone is known.
    EXPECT_EQ(chosenMaterialName(own), "tourmaline");
    EXPECT_EQ(chosenMaterialName(shipped), "tourmaline");
    own.constantIndex = 1.6;
    EXPECT_EQ(chosenMaterialName(own), "a constant n");
}

}  // namespace
}  // namespace facetlight
