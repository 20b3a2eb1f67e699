// GemCad reading rules that real published designs need (issue 27): each case failed or went wrong before.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "cuts/cut_library.h"
#include "cuts/design_shape.h"
#include "io/cutting_sheet.h"
#include "io/gemcad_design.h"
#include "io/gemcad_writer.h"
#include "io/mesh_io.h"
#include "scene/scene.h"
#include "stone/stone.h"
#include "stone/stone_size.h"
#include "support/expect_error.h"
#include "util/error.h"

using namespace facetlight;
using facetlight::test::expectError;
using facetlight::test::readFileBytes;

namespace {

std::map<std::string, Vec3> facetNormals(const Stone& s) {
    std::map<std::string, Vec3> normals;
    for (const auto& f : s.facets) normals[f.name] = f.normal;
    return normals;
}

// An octahedron-like design with a table and a culet, on a gear line given by the caller.
std::string pointedDesign(const std::string& gearLine, const std::string& indices) {
    return "GemCad 5.0\n" + gearLine + "\na -45 1 " + indices + " n P\na 45 1 " + indices +
           " n C\na 90 1.1 " + indices + " n G\na 0 0.9 n T\n";
}


// In [0, 360), a hair below 360 (atan2 of -0) read as 0.
double azimuthDeg(const Vec3& n) {
    const double phi = std::fmod(degrees(std::atan2(n.x, n.y)) + 360, 360);
    return phi > 360 - 1e-9 ? 0 : phi;
}

}  // namespace

TEST(GemCadDesign, NegativeGearNumbersTheTeethTheOtherWay) {
    // GemCad's negative gear: index 24 of 96 lies a quarter turn counter-clockwise from +y, at -x.
    const Stone s = Stone::build(parseGemCad(pointedDesign("g -96 0.0", "96 24 48 72")), "minus");
    const auto n = facetNormals(s);
    ASSERT_TRUE(n.count("P_2")) << s.facets.size();
    EXPECT_NEAR(azimuthDeg(n.at("P_2")), 270, 1e-9);
    EXPECT_NEAR(azimuthDeg(n.at("P_1")), 0, 1e-9);
    EXPECT_EQ(s.facets.size(), 13u);
}

TEST(GemCadDesign, NegativeAndFullTurnIndicesWrapAroundTheGear) {
    const Stone s = Stone::build(parseGemCad(pointedDesign("g 96 0", "-96 -72 -48 -24")), "wrapped");
    const auto n = facetNormals(s);
    EXPECT_NEAR(azimuthDeg(n.at("P_2")), 90, 1e-9);  // -72 is index 24: +x
    EXPECT_NEAR(azimuthDeg(n.at("P_4")), 270, 1e-9);
    const GemCadDesign d = parseGemCadDesign(pointedDesign("g 96 0", "0 24 48 72"));
    EXPECT_NEAR(gemCadAzimuthDeg(d, -24), 270, 1e-12);
    EXPECT_NEAR(gemCadAzimuthDeg(d, 120), 90, 1e-12);
}

TEST(GemCadDesign, IndicesContinuedOnTheNextLineAreKept) {
    const std::string design =
        "GemCad 5.0\ng 96 0\na -45 1 96 24\n48 n Pmain\n72 G Pavilion mains\n"
        "a 45 1 96 24 48 72 n C\na 90 1.1 96 24 48 72 n G\na 0 0.9 n T\n";
    const GemCadDesign d = parseGemCadDesign(design);
    ASSERT_EQ(d.tiers.size(), 4u);
    ASSERT_EQ(d.tiers[0].facets.size(), 4u);
    EXPECT_EQ(d.tiers[0].name, "Pmain");
    EXPECT_EQ(d.tiers[0].facets[2].name, "Pmain");
    EXPECT_EQ(d.tiers[0].instructions, "Pavilion mains");
    EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
    EXPECT_EQ(Stone::build(buildGemCadMesh(d), "continued").facets.size(), 13u);
}

TEST(GemCadDesign, LineEndingsEncodingsAndGluedKeywords) {
    std::string crlf = pointedDesign("g96 0.0", "96 24 48 72");
    std::string windows;
    for (char c : crlf) windows += c == '\n' ? std::string("\r\n") : std::string(1, c);
    windows.insert(windows.find("g96"), "H Angles in \xB0 (Windows-1252)\r\ny 4 y\rI 1.54\r\n");
    const GemCadDesign d = parseGemCadDesign("\xEF\xBB\xBF" + windows);
    EXPECT_EQ(d.gear, 96);
    EXPECT_EQ(d.symmetry, 4);
    EXPECT_TRUE(d.mirror);
    ASSERT_TRUE(d.refractiveIndex.has_value());
    EXPECT_DOUBLE_EQ(*d.refractiveIndex, 1.54);
    ASSERT_EQ(d.headers.size(), 1u);
    EXPECT_EQ(d.headers[0], "Angles in \xC2\xB0 (Windows-1252)");  // read as Windows-1252, kept as UTF-8
    EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
    EXPECT_EQ(d.tiers.size(), 4u);
}

TEST(GemCadDesign, AGearLineWithoutItsKeyword) {
    // As in a published design (tests/data/gemcad/SOURCES.md, astryx-star.asc): "96 0.0" before the tiers.
    std::string design = pointedDesign("96 0.0", "96 24 48 72");
    const GemCadDesign d = parseGemCadDesign(design);
    EXPECT_EQ(d.gear, 96);
    EXPECT_TRUE(d.warnings.empty()) << d.warnings.front();
}

TEST(GemCadDesign, CuletWithNegativeDistance) {
    // GemCad's manual: the distance is negative for a culet, a 0-degree pavilion facet.
    const std::string design = pointedDesign("g 96 0", "96 24 48 72") + "a 0 -0.6 0 n K\n";
    const Stone s = Stone::build(parseGemCad(design), "culet");
    const auto n = facetNormals(s);
    ASSERT_TRUE(n.count("K"));
    EXPECT_NEAR(n.at("K").z, -1, 1e-12);
    EXPECT_EQ(s.facets.size(), 14u);
}

TEST(GemCadDesign, PrintedPrecisionSetsTheWeld) {
    EXPECT_DOUBLE_EQ(parseGemCadDesign(pointedDesign("g 96 0", "96 24 48 72")).distancePrecision, 0);
    const std::string printed =
        "GemCad 5.0\ng 96 0\na -45 1.000000 96 24 48 72\na 45 1.00000000 96 24 48 72\na 0 0.900000\n";
    EXPECT_DOUBLE_EQ(parseGemCadDesign(printed).distancePrecision, 5e-7);
}

// Four pavilion facets whose distances are exact only to the 6 printed decimals: their apex is four points
// up to 1e-6 apart, which used to leave slivers at the culet instead of one meet.
TEST(GemCadDesign, MeetExactOnlyToThePrintedPrecisionIsOneVertex) {
    const std::string design =
        "GemCad 5.0\ng 96 0\na -45 1.000000 96\na -45 1.000001 24\na -45 0.999999 48\na -45 1.000000 72\n"
        "a 45 1.000000 96 24 48 72\na 90 1.100000 96 24 48 72\na 0 0.900000\n";
    const PolygonMesh mesh = parseGemCad(design);
    const Stone s = Stone::build(mesh, "apex");
    EXPECT_EQ(s.facets.size(), 13u);
    // The pavilion's four facets share one lowest vertex.
    double lowest = 0;
    for (const Vec3& v : mesh.vertices) lowest = std::min(lowest, v.z);
    int atApex = 0;
    for (const Vec3& v : mesh.vertices) atApex += v.z < lowest + 1e-5;
    EXPECT_EQ(atApex, 1);
}

TEST(GemCadDesign, AStoneWithoutATableIsNotTipped) {
    // A checkerboard-like crown of four facets: no facet faces up, and the largest must not be turned up.
    const std::string design =
        "GemCad 5.0\ng 96 0\na -50 1 12 36 60 84 n P\na 30 1 12 36 60 84 n C\na 90 1.2 12 36 60 84 n G\n";
    const Stone s = Stone::build(parseGemCad(design), "notable");
    EXPECT_TRUE(s.frame.fileOrientation);
    EXPECT_TRUE(s.frame.tableFacet.empty());
    for (const auto& f : s.facets) {
        if (f.name.rfind("C_", 0) != 0) continue;
        EXPECT_NEAR(std::acos(f.normal.z), radians(30), 1e-9) << f.name;
    }
    EXPECT_NEAR(azimuthDeg(facetNormals(s).at("C_1")), 45, 1e-9);
}

TEST(GemCadDesign, ALongDesignKeepsItsGearAzimuths) {
    // Long along y (index 0): the gear index 0 stays +y, it is not laid along x.
    const std::string design =
        "GemCad 5.0\ng 96 0\na -42 1.6 96 48 n P1\na -42 1 24 72 n P2\na 35 1.6 96 48 n C1\na 35 1 24 72 n C2\n"
        "a 90 1.8 96 48 n G1\na 90 1.1 24 72 n G2\na 0 0.7 n T\n";
    const Stone s = Stone::build(parseGemCad(design), "long");
    EXPECT_TRUE(s.frame.fileOrientation);
    EXPECT_FALSE(s.frame.longAxisTurned);
    EXPECT_NEAR(azimuthDeg(facetNormals(s).at("G1_1")), 0, 1e-9);
    EXPECT_GT(s.bounds.extent().y, s.bounds.extent().x);
    EXPECT_GT(s.proportions.length, s.proportions.width);
}

TEST(GemCadDesign, AMeshIsReorientedOnlyWhenItMustBeAndSaysSo) {
    // The same tableless stone as an OBJ-like mesh: turned so its largest facet faces up, and recorded.
    const std::string design =
        "GemCad 5.0\ng 96 0\na -50 1 12 36 60 84 n P\na 30 1 12 36 60 84 n C\na 90 1.2 12 36 60 84 n G\n";
    PolygonMesh mesh = parseGemCad(design);
    mesh.design = nullptr;  // as a mesh file would come
    const Stone turned = Stone::build(mesh, "mesh");
    EXPECT_FALSE(turned.frame.fileOrientation);
    EXPECT_FALSE(turned.frame.tableFacet.empty());
    EXPECT_GT(turned.frame.turnedDeg, 1);
    StoneOptions keep;
    keep.keepFrame = true;
    const Stone kept = Stone::build(mesh, "mesh", keep);
    EXPECT_TRUE(kept.frame.fileOrientation);
    EXPECT_TRUE(kept.frame.tableFacet.empty());
}

TEST(GemCadDesign, TheFilesIndexIsTracedUnlessTheJobNamesAMaterial) {
    const Stone s = Stone::build(parseGemCad(pointedDesign("g 96 0\nI 1.54", "96 24 48 72")), "quartz");
    ASSERT_TRUE(s.design && s.design->refractiveIndex);
    SceneSettings settings;  // material "auto"
    MaterialChoice chosen = chooseMaterial(settings, s);
    EXPECT_DOUBLE_EQ(chosen.material.indexD(), 1.54);
    EXPECT_EQ(chosen.source, "design file");
    settings.material = "diamond";
    chosen = chooseMaterial(settings, s);
    EXPECT_NEAR(chosen.material.indexD(), 2.417, 0.001);
    EXPECT_EQ(chosen.source, "material");
    settings.material = "auto";
    settings.constantIndex = 1.7;
    EXPECT_EQ(chooseMaterial(settings, s).source, "n");
    const Stone plain = Stone::build(parseGemCad(pointedDesign("g 96 0", "96 24 48 72")), "plain");
    EXPECT_EQ(chooseMaterial(SceneSettings{}, plain).source, "default");
}

TEST(GemCadDesign, Errors) {
    auto refused = [](const std::string& text, const std::string& fragment) {
        expectError([&] { parseGemCad(text); }, fragment);
    };
    refused("GemCad 5.0\ng 0 0\n", "GemCad line 2: the gear '0' must be a whole number");
    refused("GemCad 5.0\ng 96 0\nI 0.5\n", "GemCad line 3: the refractive index '0.5' must lie between 1 and 5");
    refused("GemCad 5.0\ng 96 0\na -45 1\n\n", "GemCad line 3: the tier lists no index");
    refused("GemCad 5.0\ng 96 0\na -45 -1 0\n", "GemCad line 3: the distance must be positive");
}

// ---- Writing, tweaking, the cutting sheet and the weight ----

namespace {

const std::string kBrilliant = std::string(FACETLIGHT_SOURCE_DIR) + "/tests/data/brilliant.asc";


}  // namespace

TEST(GemCadDesign, WrittenDesignReadsBackTheSame) {
    const GemCadDesign d = parseGemCadDesign(readFileBytes(kBrilliant));
    const GemCadDesign again = parseGemCadDesign(writeGemCad(d));
    ASSERT_EQ(again.tiers.size(), d.tiers.size());
    EXPECT_EQ(again.gear, d.gear);
    EXPECT_EQ(again.symmetry, d.symmetry);
    EXPECT_EQ(again.mirror, d.mirror);
    EXPECT_EQ(again.refractiveIndex, d.refractiveIndex);
    EXPECT_EQ(again.headers, d.headers);
    EXPECT_EQ(again.footnotes, d.footnotes);
    for (size_t t = 0; t < d.tiers.size(); ++t) {
        EXPECT_EQ(again.tiers[t].angleDeg, d.tiers[t].angleDeg);
        EXPECT_EQ(std::signbit(again.tiers[t].angleDeg), std::signbit(d.tiers[t].angleDeg));
        EXPECT_EQ(again.tiers[t].distance, d.tiers[t].distance);
        EXPECT_EQ(again.tiers[t].name, d.tiers[t].name);
        EXPECT_EQ(again.tiers[t].instructions, d.tiers[t].instructions);
        ASSERT_EQ(again.tiers[t].facets.size(), d.tiers[t].facets.size());
        for (size_t f = 0; f < d.tiers[t].facets.size(); ++f) {
            EXPECT_EQ(again.tiers[t].facets[f].index, d.tiers[t].facets[f].index);
            EXPECT_EQ(again.tiers[t].facets[f].name, d.tiers[t].facets[f].name);
        }
    }
}

TEST(GemCadDesign, LibraryShapeWrittenAsAscRebuildsTheSameStone) {
    const Stone original = Stone::build(makeCut("round_brilliant"), "round_brilliant");
    const std::string asc = writeGemCad(gemCadDesignOf(original));
    const Stone again = Stone::build(parseGemCad(asc), "again");
    ASSERT_EQ(again.facets.size(), original.facets.size());
    EXPECT_NEAR(again.volume(), original.volume(), 1e-7 * original.volume());
    // Every facet of the original has one in the rebuilt stone with the same plane, to what the original's
    // outlines tell (a narrow girdle facet's Newell normal is good to a few 1e-7) and the girdle band's
    // centring (a few 1e-7 of the size).
    for (const Facet& f : original.facets) {
        const Facet* same = nullptr;
        for (const Facet& g : again.facets)
            if (!same || length(f.normal - g.normal) < length(f.normal - same->normal)) same = &g;
        EXPECT_LT(length(f.normal - same->normal), 1e-6) << f.name;
        EXPECT_NEAR(f.offset, same->offset, 1e-6) << f.name;
    }
    EXPECT_NEAR(*again.proportions.pavilionAngleDeg, *original.proportions.pavilionAngleDeg, 1e-6);
}

TEST(GemCadDesign, TweakedTierTurnsAboutItsGirdleMeet) {
    const auto file = fileShape(kBrilliant);
    ASSERT_TRUE(file->design);
    std::vector<std::string> names;
    for (const CutParameter& p : file->shape.parameters) names.push_back(p.name);
    EXPECT_EQ(names, (std::vector<std::string>{"tier:P1", "tier:P2", "tier:C1", "tier:C2", "tier:C3"}));
    // Unchanged values cut the design exactly as drawn.
    const PolygonMesh same = file->shape.build(completeCutValues(file->shape, {}));
    EXPECT_EQ(same.vertices, file->built->vertices);

    const Stone before = Stone::build(*file->built, "before");
    const Stone after = Stone::build(file->shape.build({{"tier:P1", 42}}), "after");
    double slope = 0, girdleRadiusBefore = 0, girdleRadiusAfter = 0;
    for (const Facet& f : after.facets)
        if (f.name == "P1_1") slope = degrees(std::acos(-f.normal.z));
    EXPECT_NEAR(slope, 42, 1e-9);
    for (const Vec3& v : before.vertices) girdleRadiusBefore = std::max(girdleRadiusBefore, std::hypot(v.x, v.y));
    for (const Vec3& v : after.vertices) girdleRadiusAfter = std::max(girdleRadiusAfter, std::hypot(v.x, v.y));
    EXPECT_NEAR(girdleRadiusAfter, girdleRadiusBefore, 1e-9);  // the girdle stays
    EXPECT_GT(*after.proportions.pavilionDepthPct, *before.proportions.pavilionDepthPct);  // steeper: deeper
    // Written back, the tweak opens as the same stone.
    const Stone reread = Stone::build(parseGemCad(writeGemCad(file->designAt({{"tier:P1", 42}}))), "reread");
    EXPECT_NEAR(reread.volume(), after.volume(), 1e-6 * after.volume());
    expectError([&] { completeCutValues(file->shape, {{"tier:P9", 40}}); }, "has no parameter 'tier:P9'");
    expectError([&] { completeCutValues(file->shape, {{"tier:P1", 95}}); }, "must lie between 1 and 89");
}

TEST(GemCadDesign, CuttingSheetMeasuresEveryTierBack) {
    const Stone s = loadStone(kBrilliant);
    const std::optional<CuttingSheet> sheet = cuttingSheet(s);
    ASSERT_TRUE(sheet);
    EXPECT_EQ(sheet->source, "GemCad design");
    ASSERT_EQ(sheet->tiers.size(), 7u);
    for (const SheetTier& t : sheet->tiers) {
        EXPECT_EQ(t.facetsCut, t.facets) << t.name;
        ASSERT_TRUE(t.measuredAngleDeg) << t.name;
        EXPECT_NEAR(*t.measuredAngleDeg, t.angleDeg, 0.01) << t.name;
    }
    auto meets = [&](const std::string& a, const std::string& b) {
        for (const SheetTier& t : sheet->tiers)
            if (t.name == a) return std::find(t.meets.begin(), t.meets.end(), b) != t.meets.end();
        return false;
    };
    EXPECT_TRUE(meets("T", "C2"));   // the table meets the stars
    EXPECT_TRUE(meets("P1", "P2"));  // the pavilion mains meet the lower halves
    EXPECT_FALSE(meets("T", "P1"));
    const std::string text = cuttingSheetText(*sheet);
    EXPECT_NE(text.find("P1         pavilion    41.00     41.00   0.668000   8/8    03-15-27-39-51-63-75-87"),
              std::string::npos)
        << text;
    // A convex mesh gets a sheet measured from its facets.
    const Stone mesh = Stone::build(makeCut("round_brilliant"), "rb");
    const std::optional<CuttingSheet> measured = cuttingSheet(mesh);
    ASSERT_TRUE(measured);
    EXPECT_EQ(measured->source, "measured from the mesh");
    size_t facets = 0;
    for (const SheetTier& t : measured->tiers) facets += t.facetsCut;
    EXPECT_EQ(facets, mesh.facets.size());
}

// The weight against the trade's estimate for a round brilliant, carats = diameter^2 x depth x 0.0061
// (mm; the "0.0061 formula" of diamond graders, e.g. GIA's Diamond Grading course): an independent check of
// the volume, the scale and the density.
TEST(GemCadDesign, WeightAgreesWithTheTradesEstimate) {
    const Stone s = Stone::build(makeCut("round_brilliant"), "rb");
    const StoneSize size = stoneSize(s, 6.5, Material::byName("diamond").densityGcm3());
    ASSERT_TRUE(size.carats);
    const double estimate = 6.5 * 6.5 * size.depthMm * 0.0061;
    EXPECT_NEAR(*size.carats, estimate, 0.05 * estimate);
    EXPECT_NEAR(size.lengthMm, 6.5, 1e-9);
    EXPECT_GT(size.blockRetention, 0.3);
    EXPECT_LT(size.blockRetention, 0.6);
    EXPECT_FALSE(stoneSize(s, 6.5, std::nullopt).carats);
}

// The yield from a rough: the share of its volume the stone keeps, refused when the stone sticks out of it.
TEST(GemCadDesign, RoughRetentionIsTheVolumeShareOfAStoneInsideItsRough) {
    auto box = [](double lo, double hi) {
        std::string obj;
        for (int i = 0; i < 8; ++i)
            obj += "v " + std::to_string(i & 1 ? hi : lo) + " " + std::to_string(i & 2 ? hi : lo) + " " +
                   std::to_string(i & 4 ? hi : lo) + "\n";
        return obj + "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";
    };
    StoneOptions asDrawn;
    asDrawn.keepFrame = true;
    const Stone stone = Stone::build(parseObj(box(0, 1)), "stone", asDrawn);
    // A rough from -1 to 3: 64 times the stone's volume, the stone off its centre but inside.
    EXPECT_NEAR(roughRetention(stone, Stone::build(parseObj(box(-1, 3)), "rough", asDrawn)), 1.0 / 64, 1e-12);
    expectError([&] { roughRetention(stone, Stone::build(parseObj(box(0.5, 4)), "small", asDrawn)); },
                "the stone does not fit inside the rough 'small'");
}
