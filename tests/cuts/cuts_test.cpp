// The cut library: round brilliant proportions measured back, refusals, every shape, the shipped meshes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cuts/cut_library.h"
#include "cuts/fancy_cuts.h"
#include "cuts/mesh_resolver.h"
#include "cuts/round_brilliant.h"
#include "cuts/step_cuts.h"
#include "io/mesh_io.h"
#include "io/obj_writer.h"
#include "stone/proportions.h"
#include "stone/stone.h"
#include "stone/stone_json.h"
#include "util/error.h"
#include "util/number_text.h"

using namespace facetlight;
using ::testing::HasSubstr;

namespace {

Stone buildRound(const RoundBrilliantParams& p) {
    return Stone::build(makeRoundBrilliant(p), "round");
}

const Facet& facetNamed(const Stone& s, const std::string& name) {
    for (const auto& f : s.facets)
        if (f.name == name) return f;
    throw std::runtime_error("no facet " + name);
}

// Star % and lower-half % read back from the mesh: the star tip is the star's outermost vertex, the
// lower-half point the lower half's innermost, both on the ridge at 22.5 deg.
double measuredStarPct(const Stone& s, double tablePct) {
    double tip = 0;
    for (uint32_t v : facetNamed(s, "star_1").outline)
        tip = std::max(tip, std::hypot(s.vertices[v].x, s.vertices[v].y));
    const double edge = tablePct / 200 * std::cos(radians(22.5));
    return 100 * (tip - edge) / (0.5 - edge);
}
double measuredLowerHalfPct(const Stone& s) {
    double inner = 1;
    for (uint32_t v : facetNamed(s, "lower_half_1").outline)
        inner = std::min(inner, std::hypot(s.vertices[v].x, s.vertices[v].y));
    return 100 * (0.5 - inner) / 0.5;
}

template <class F>
std::string errorOf(F&& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}


// The trade's halves, computed independently of the generator: each half holds the horizontal chord from its
// main's girdle point to the 22.5-deg girdle point (so it faces 11.25 deg off the main) and the mains' meeting
// point on the 22.5-deg ridge, `lengthPct` of the way from the girdle (lower halves: toward the centre; upper
// halves: the star tip, from the table edge outward).
double tradeLowerHalfDeg(double pavilionDeg, double lowerHalfPct) {
    const double r = 0.5 * (1 - lowerHalfPct / 100);
    return degrees(std::atan(std::tan(radians(pavilionDeg)) * (0.5 - r * std::cos(radians(22.5))) /
                             ((0.5 - r) * std::cos(radians(11.25)))));
}
double tradeUpperHalfDeg(double tablePct, double crownDeg, double starPct) {
    const double edge = tablePct / 200 * std::cos(radians(22.5)), tip = edge + starPct / 100 * (0.5 - edge);
    return degrees(std::atan(std::tan(radians(crownDeg)) * (0.5 - tip * std::cos(radians(22.5))) /
                             ((0.5 - tip) * std::cos(radians(11.25)))));
}

double slopeOf(const Facet& f) { return degrees(std::acos(std::fabs(f.normal.z))); }
double azimuthOf(const Facet& f) { return degrees(std::atan2(f.normal.y, f.normal.x)); }

}  // namespace

TEST(RoundBrilliant, GiaReferenceMatchesPublishedFigures) {
    const Stone s = buildRound({});
    const Proportions& p = s.proportions;
    EXPECT_NEAR(*p.tablePct, 57, 0.05);
    EXPECT_NEAR(*p.crownAngleDeg, 34.0, 0.01);
    EXPECT_NEAR(*p.pavilionAngleDeg, 40.7, 0.01);
    EXPECT_NEAR(*p.girdlePct, 2.5, 0.01);  // where thinnest
    EXPECT_NEAR(*p.crownHeightPct, 14.5, 0.05);
    EXPECT_NEAR(*p.pavilionDepthPct, 43.0, 0.05);
    // The halves take the girdle down by tan(half) (1 - cos 11.25) / 2 each side between the mains' points.
    const double dip = 50 * (1 - std::cos(radians(11.25)));
    const double thickest = 2.5 + dip * (std::tan(radians(tradeUpperHalfDeg(57, 34, 50))) +
                                         std::tan(radians(tradeLowerHalfDeg(40.7, 80))));
    EXPECT_NEAR(*p.girdleThickestPct, thickest, 0.01);
    EXPECT_NEAR(*p.totalDepthPct, *p.crownHeightPct + thickest + *p.pavilionDepthPct, 0.01);
    EXPECT_NEAR(measuredStarPct(s, 57), 50, 0.05);
    EXPECT_NEAR(measuredLowerHalfPct(s), 80, 0.05);
    EXPECT_NEAR(*p.starPct, 50, 0.05);
    EXPECT_NEAR(*p.lowerHalfPct, 80, 0.05);
    EXPECT_TRUE(s.convex);
    EXPECT_EQ(s.facetCount(Region::Table), 1);
    EXPECT_EQ(s.facetCount(Region::Crown), 32);
    EXPECT_EQ(s.facetCount(Region::Pavilion), 24);
    EXPECT_EQ(s.facetCount(Region::Girdle), 64);
    for (const char* name :
         {"table", "star_8", "bezel_1", "upper_half_16", "girdle_64", "pavilion_main_8", "lower_half_16"})
        EXPECT_NO_THROW(facetNamed(s, name)) << name;
}

// DiamCalc gives 42.24 deg for these proportions (PriceScope cut study; shared optics reference); read off the
// built mesh, every lower half must agree. The faceters' layout (3.75 deg off the mains) gave 41.39.
TEST(RoundBrilliant, TradeHalvesMeasuredBackFromTheMesh) {
    RoundBrilliantParams in;
    in.tablePct = 56, in.crownAngleDeg = 35, in.pavilionAngleDeg = 41.15, in.lowerHalfPct = 80;
    const Stone s = buildRound(in);
    int lower = 0, upper = 0;
    for (const auto& f : s.facets) {
        const double offMain = std::fabs(std::remainder(azimuthOf(f), 45.0));
        if (f.name.rfind("lower_half_", 0) == 0) {
            ++lower;
            EXPECT_NEAR(slopeOf(f), 42.24, 0.02) << f.name;
            EXPECT_NEAR(slopeOf(f), 42.2385, 1e-3) << f.name;
            EXPECT_NEAR(offMain, 11.25, 1e-6) << f.name;
        } else if (f.name.rfind("upper_half_", 0) == 0) {
            ++upper;
            EXPECT_NEAR(slopeOf(f), tradeUpperHalfDeg(56, 35, 50), 1e-6) << f.name;
            EXPECT_NEAR(offMain, 11.25, 1e-6) << f.name;
        }
    }
    EXPECT_EQ(lower, 16);
    EXPECT_EQ(upper, 16);
    EXPECT_NEAR(*s.proportions.lowerHalfAngleDeg, 42.24, 0.02);
    EXPECT_NEAR(*s.proportions.upperHalfAngleDeg, tradeUpperHalfDeg(56, 35, 50), 1e-6);
    EXPECT_NEAR(*s.proportions.girdlePct, 2.5, 1e-6);
    EXPECT_GT(*s.proportions.girdleThickestPct, 4.0);  // at the mains' points and the halves' junctions
}

TEST(RoundBrilliant, FaceterHalvesAreAnotherStone) {
    RoundBrilliantParams in;
    in.tablePct = 56, in.crownAngleDeg = 35, in.pavilionAngleDeg = 41.15, in.lowerHalfPct = 80;
    in.halves = HalvesLayout::Faceter;
    const Stone s = buildRound(in);
    const Facet& half = facetNamed(s, "lower_half_1");
    EXPECT_NEAR(azimuthOf(half), 3.75, 1e-6);
    EXPECT_NEAR(slopeOf(half), 41.39, 0.01);
    EXPECT_NEAR(*s.proportions.girdlePct, 2.5, 1e-6);
    EXPECT_NEAR(*s.proportions.lowerHalfPct, 80, 0.05);
    EXPECT_EQ(makeCut("round_brilliant", {{"halves", 1}}).polygons.size(),
              makeRoundBrilliant([] {
                  RoundBrilliantParams f;
                  f.halves = HalvesLayout::Faceter;
                  return f;
              }()).polygons.size());
    EXPECT_THAT(cutCommandLine(findCutShape("round_brilliant"),
                               completeCutValues(findCutShape("round_brilliant"), {{"halves", 1}})),
                HasSubstr("--halves faceter"));
    EXPECT_THAT(errorOf([] { choiceIndex(findCutShape("round_brilliant").parameters.back(), "gemcad"); }),
                HasSubstr("halves 'gemcad': must be one of trade, faceter"));
}

TEST(RoundBrilliant, TolkowskyKnifeEdge) {
    RoundBrilliantParams t;
    t.tablePct = 53, t.crownAngleDeg = 34.5, t.pavilionAngleDeg = 40.75, t.girdlePct = 0;
    const Stone s = buildRound(t);
    const Proportions& p = s.proportions;
    EXPECT_NEAR(*p.girdlePct, 0, 1e-9);
    EXPECT_NEAR(*p.crownHeightPct, 16.2, 0.06);  // 16.15 unrounded: (1 - 0.53) / 2 * tan 34.5
    EXPECT_NEAR(*p.pavilionDepthPct, 43.1, 0.05);
    EXPECT_NEAR(*p.crownAngleDeg, 34.5, 0.01);
    EXPECT_NEAR(*p.pavilionAngleDeg, 40.75, 0.01);
    EXPECT_EQ(s.facetCount(Region::Girdle), 0);
    EXPECT_EQ(s.facetCount(Region::Crown), 32);
    EXPECT_NEAR(p.diameter, 1.0, 1e-9);
}

struct Sweep {
    double table, crown, pavilion, girdle, star, lowerHalf, culet;
    int girdleFacets;
};

class RoundBrilliantSweep : public ::testing::TestWithParam<Sweep> {};

TEST_P(RoundBrilliantSweep, ProportionsMeasuredBackMatchInputs) {
    const Sweep& w = GetParam();
    RoundBrilliantParams in{w.table, w.crown,     w.pavilion, w.girdle,
                            w.star,  w.lowerHalf, w.culet,    w.girdleFacets};
    const Stone s = buildRound(in);
    const Proportions& p = s.proportions;
    const double T = w.table / 100, c = w.culet / 100;
    EXPECT_NEAR(*p.tablePct, w.table, 0.05);
    EXPECT_NEAR(*p.crownAngleDeg, w.crown, 0.01);
    EXPECT_NEAR(*p.pavilionAngleDeg, w.pavilion, 0.01);
    EXPECT_NEAR(*p.girdlePct, w.girdle, 1e-6);
    EXPECT_GT(*p.girdleThickestPct, w.girdle);
    EXPECT_NEAR(*p.lowerHalfAngleDeg, tradeLowerHalfDeg(w.pavilion, w.lowerHalf), 1e-6);
    EXPECT_NEAR(*p.upperHalfAngleDeg, tradeUpperHalfDeg(w.table, w.crown, w.star), 1e-6);
    EXPECT_NEAR(*p.crownHeightPct, 100 * (1 - T) / 2 * std::tan(radians(w.crown)), 0.05);
    EXPECT_NEAR(*p.pavilionDepthPct, 100 * (1 - c) / 2 * std::tan(radians(w.pavilion)), 0.05);
    EXPECT_NEAR(measuredStarPct(s, w.table), w.star, 0.05);
    EXPECT_NEAR(measuredLowerHalfPct(s), w.lowerHalf, 0.05);
    EXPECT_TRUE(s.convex);
    EXPECT_EQ(s.facetCount(Region::Table), 1);
    EXPECT_EQ(s.facetCount(Region::Crown), 32);
    EXPECT_EQ(s.facetCount(Region::Pavilion), 24 + (w.culet > 0 ? 1 : 0));
    EXPECT_EQ(s.facetCount(Region::Girdle), w.girdle == 0 ? 0 : w.girdleFacets == 0 ? 64 : w.girdleFacets);
}

INSTANTIATE_TEST_SUITE_P(
    Designs, RoundBrilliantSweep,
    ::testing::Values(Sweep{57, 34, 40.7, 2.5, 50, 80, 0, 32}, Sweep{57, 34, 40.7, 2.5, 50, 80, 0, 80},
                      Sweep{53, 34.5, 40.75, 1, 45, 75, 0, 96}, Sweep{62, 31.5, 41.8, 4, 65, 85, 1.5, 0},
                      Sweep{52, 36.5, 40.6, 3, 40, 70, 3, 64}, Sweep{60, 33, 42.5, 2, 55, 78, 0, 128},
                      Sweep{42, 40, 41.5, 1.5, 55, 55, 12, 16}));

TEST(RoundBrilliant, RefusesImpossibleInputsNamingThem) {
    RoundBrilliantParams p;
    p.tablePct = 100;
    EXPECT_THAT(errorOf([&] { makeRoundBrilliant(p); }),
                HasSubstr("table 100: a table this wide swallows the crown"));
    p = {};
    p.starPct = 100;
    EXPECT_THAT(errorOf([&] { makeRoundBrilliant(p); }),
                HasSubstr("star 100: stars this long reach the girdle"));
    p = {};
    p.lowerHalfPct = 95, p.culetPct = 20;
    EXPECT_THAT(errorOf([&] { makeRoundBrilliant(p); }),
                HasSubstr("lower half 95: lower halves this long run into the culet"));
    p = {};
    p.girdleFacets = 70;
    EXPECT_THAT(errorOf([&] { makeRoundBrilliant(p); }),
                HasSubstr("girdle facets 70: use 0 (smooth) or a multiple of 16"));
    p = {};
    p.crownAngleDeg = 90;
    EXPECT_THAT(errorOf([&] { makeRoundBrilliant(p); }), HasSubstr("crown angle 90"));
}

TEST(CutLibrary, RefusesUnknownShapesParametersAndRanges) {
    EXPECT_THAT(errorOf([] { makeCut("trilliant"); }),
                HasSubstr("unknown shape 'trilliant'; the shapes are: round_brilliant"));
    EXPECT_THAT(errorOf([] {
                    makeCut("oval", {{"star_count", 3}});
                }),
                HasSubstr("oval has no parameter 'star_count'"));
    EXPECT_THAT(errorOf([] {
                    makeCut("round_brilliant", {{"table", 120}});
                }),
                HasSubstr("table 120: must lie between 20 and 90%"));
    EXPECT_THAT(errorOf([] {
                    makeCut("emerald", {{"crown_steps", 2.5}});
                }),
                HasSubstr("crown_steps 2.5: must be a whole number"));
    EXPECT_THAT(errorOf([] {
                    makeCut("round_brilliant", {{"lower_half", 95}, {"culet", 20}});
                }),
                HasSubstr("run into the culet"));
}

TEST(CutLibrary, AtLeastTenShapesWithSnakeCaseNames) {
    EXPECT_GE(cutShapes().size(), 10u);
    for (const auto& shape : cutShapes()) {
        for (char ch : shape.name) EXPECT_TRUE(std::islower(uint8_t(ch)) || ch == '_') << shape.name;
        for (const auto& p : shape.parameters) {
            EXPECT_LE(p.min, p.defaultValue) << shape.name << " " << p.name;
            EXPECT_LE(p.defaultValue, p.max) << shape.name << " " << p.name;
        }
    }
}

TEST(CutLibrary, ParametersAreTheRowsOfTheDesignTables) {
    // A shape's defaults are its design's own, and its build sets the member each row names.
    const CutValues emerald = completeCutValues(findCutShape("emerald"), {});
    EXPECT_EQ(emerald.at("ratio"), StepCutParams{}.ratio);
    EXPECT_EQ(emerald.at("pavilion_step"), StepCutParams{}.pavilionStepDeg);
    EXPECT_EQ(emerald.at("crown_steps"), StepCutParams{}.crownSteps);
    StepCutParams step;
    step.tablePct = 60, step.crownSteps = 2;
    EXPECT_EQ(objText(makeCut("emerald", {{"table", 60}, {"crown_steps", 2}})), objText(makeStepCut(step)));
    // The fancy shapes lay the faceters' halves on their outline.
    FancyBrilliantParams pear;
    pear.outline = FancyOutline::Pear, pear.ratio = 1.5, pear.tiers.halves = HalvesLayout::Faceter;
    pear.tiers.starPct = 45;
    EXPECT_EQ(objText(makeCut("pear", {{"star", 45}})), objText(makeFancyBrilliant(pear)));
    const CutParameter& halves = findCutShape("round_brilliant").parameters.back();
    EXPECT_EQ(halves.choices, (std::vector<std::string>{"trade", "faceter"}));
    EXPECT_TRUE(halves.integer);
    EXPECT_EQ(halves.max, 1);
    EXPECT_EQ(cutFlag("girdle_facets"), "--girdle-facets");
}

TEST(CutLibrary, OneTableNamesEachProportionForTheTerminalAndTheJson) {
    const Stone s = Stone::build(makeCut("round_brilliant"), "round_brilliant");
    const nlohmann::json j = proportionsJson(s.proportions);
    EXPECT_EQ(j.size(), kProportionFields.size() + 4);  // and length, width, diameter, length_to_width
    for (size_t i = 0; i < kProportionFields.size(); ++i) {
        const ProportionField& field = kProportionFields[i];
        for (size_t k = 0; k < i; ++k) {
            EXPECT_NE(field.key, kProportionFields[k].key);
            EXPECT_NE(field.label, kProportionFields[k].label);
            EXPECT_NE(field.member, kProportionFields[k].member);
        }
        ASSERT_TRUE(s.proportions.*field.member) << field.key;  // a round brilliant has every figure
        EXPECT_EQ(j.at(std::string(field.key)).get<double>(), *(s.proportions.*field.member));
    }
    EXPECT_NEAR(j.at("table_pct").get<double>(), 57, 0.05);
    EXPECT_NEAR(j.at("crown_angle_deg").get<double>(), 34, 1e-6);
    EXPECT_NEAR(j.at("pavilion_angle_deg").get<double>(), 40.7, 1e-6);
    EXPECT_NEAR(j.at("girdle_pct").get<double>(), 2.5, 1e-6);
}

struct RegionCounts {
    int table, crown, girdle, pavilion;
};

// What each shipped design is made of; fancy shapes lose a few stars and halves near their points.
const std::map<std::string, RegionCounts> kExpectedCounts = {
    {"round_brilliant", {1, 32, 64, 24}},
    {"round_brilliant_tolkowsky", {1, 32, 0, 24}},
    {"round_brilliant_deep", {1, 32, 64, 24}},
    {"round_brilliant_shallow", {1, 32, 64, 24}},
    {"old_european", {1, 32, 64, 25}},
    {"oval", {1, 32, 64, 24}},
    {"pear", {1, 29, 53, 23}},
    {"marquise", {1, 26, 42, 22}},
    {"heart", {1, 23, 47, 21}},
    {"cushion", {1, 32, 64, 24}},
    {"princess", {1, 20, 4, 20}},
    {"radiant", {1, 32, 8, 24}},
    {"emerald", {1, 24, 8, 20}},
    {"asscher", {1, 24, 8, 20}},
    {"single_cut", {1, 8, 32, 8}},
    {"rose_cut", {0, 24, 24, 1}},
};

TEST(CutLibrary, EveryShapeIsClosedConvexWithItsFacets) {
    for (const auto& shape : cutShapes()) {
        SCOPED_TRACE(shape.name);
        const Stone s = Stone::build(makeCut(shape.name), shape.name);  // throws unless closed and consistent
        EXPECT_TRUE(s.convex);
        EXPECT_GT(s.volume(), 0);
        ASSERT_TRUE(kExpectedCounts.count(shape.name));
        const RegionCounts& n = kExpectedCounts.at(shape.name);
        EXPECT_EQ(s.facetCount(Region::Table), n.table);
        EXPECT_EQ(s.facetCount(Region::Crown), n.crown);
        EXPECT_EQ(s.facetCount(Region::Girdle), n.girdle);
        EXPECT_EQ(s.facetCount(Region::Pavilion), n.pavilion);
        EXPECT_NEAR(s.proportions.width, 1.0, 1e-3);
    }
}

TEST(CutLibrary, StepCutAnglesAndTableMeasureBack) {
    const Stone s =
        Stone::build(makeCut("emerald", {{"table", 60}, {"crown", 40}, {"pavilion", 52}}), "emerald");
    EXPECT_NEAR(*s.proportions.tablePct, 60, 0.05);
    EXPECT_NEAR(*s.proportions.crownAngleDeg, 40, 0.01);
    EXPECT_NEAR(*s.proportions.pavilionAngleDeg, 52, 0.01);
    EXPECT_NEAR(s.proportions.length / s.proportions.width, 1.4, 1e-6);
}

// The crown angle measured back is the bezels' slope, whatever the outline does to the girdle's height.
TEST(CutLibrary, FancyShapesKeepTheRequestedRatioAndCrownAngle) {
    for (const char* name : {"oval", "pear", "marquise", "radiant", "heart", "cushion"}) {
        for (double ratio : {1.1, 1.7}) {
            const Stone s = Stone::build(makeCut(name, {{"ratio", ratio}, {"crown", 33}}), name);
            EXPECT_NEAR(s.proportions.length / s.proportions.width, ratio, 2e-3) << name << ' ' << ratio;
            EXPECT_NEAR(*s.proportions.crownAngleDeg, 33, 0.01) << name << ' ' << ratio;
        }
    }
}

TEST(ObjWriter, RoundTripKeepsFacetNamesAndGeometry) {
    const PolygonMesh mesh = makeCut("round_brilliant");
    const Stone direct = Stone::build(mesh, "direct");
    const Stone loaded = Stone::build(parseObj(objText(mesh, "a header\nsecond line")), "loaded");
    ASSERT_EQ(loaded.facets.size(), direct.facets.size());
    for (size_t i = 0; i < direct.facets.size(); ++i) EXPECT_EQ(loaded.facets[i].name, direct.facets[i].name);
    EXPECT_NEAR(*loaded.proportions.crownHeightPct, *direct.proportions.crownHeightPct, 1e-6);
    // A Stone written out reads back as the same stone.
    const Stone again = Stone::build(parseObj(objText(direct)), "again");
    EXPECT_EQ(again.facets.size(), direct.facets.size());
    EXPECT_NEAR(again.volume(), direct.volume(), 1e-9);
}

TEST(MeshResolver, ShapeNamesBuildTheDefaultDesign) {
    const Stone s = resolveStone("round_brilliant");
    EXPECT_EQ(s.name, "round_brilliant");
    EXPECT_EQ(s.facetCount(Region::Crown), 32);
    EXPECT_THAT(errorOf([] { resolveStone("no_such_shape_or_file"); }),
                HasSubstr("the shipped shapes are: round_brilliant"));
}

// Text equal line by line, numbers equal to the last printed digit give or take one: the generator's
// floating point may differ in the last bit between compilers and CPUs.
void expectSameObj(const std::string& shipped, const std::string& generated, const std::string& name) {
    std::istringstream a(shipped), b(generated);
    std::string la, lb;
    int line = 0;
    while (true) {
        const bool ga = bool(std::getline(a, la)), gb = bool(std::getline(b, lb));
        ++line;
        ASSERT_EQ(ga, gb) << name << ": line counts differ at line " << line;
        if (!ga) break;
        if (la == lb) continue;
        std::istringstream ta(la), tb(lb);
        std::string wa, wb;
        while (ta >> wa) {
            ASSERT_TRUE(bool(tb >> wb)) << name << " line " << line;
            double x, y;
            if (wa != wb) {
                ASSERT_TRUE(parseNumber(wa, x) && parseNumber(wb, y) && std::fabs(x - y) <= 2e-9)
                    << name << " line " << line << ": '" << la << "' vs '" << lb << "'";
            }
        }
        ASSERT_FALSE(bool(tb >> wb)) << name << " line " << line;
    }
}

TEST(ShippedMeshes, MatchTheGeneratorAndLoad) {
    for (const auto& shape : cutShapes()) {
        SCOPED_TRACE(shape.name);
        const std::string path = std::string(FACETLIGHT_SOURCE_DIR) + "/meshes/" + shape.name + ".obj";
        std::ifstream file(path, std::ios::binary);
        ASSERT_TRUE(file) << path << " is missing: run scripts/make-meshes";
        const std::string shipped((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
        const CutValues values = completeCutValues(shape, {});
        expectSameObj(shipped,
                      objText(shape.build(values), "facetlight cut " + cutCommandLine(shape, values)),
                      shape.name);
        const Stone loaded = loadStone(path);
        const Stone built = Stone::build(makeCut(shape.name), shape.name);
        EXPECT_EQ(loaded.facets.size(), built.facets.size());
        EXPECT_EQ(loaded.convex, built.convex);
        EXPECT_NEAR(loaded.volume(), built.volume(), 1e-6);
    }
}
