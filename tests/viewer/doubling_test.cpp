#include "viewer/doubling.h"

#include "pictures/doubling_picture.h"
#include "study/job_request.h"
#include "study/study.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "optics/birefringence.h"
#include "optics/material.h"
#include "support/expect_error.h"
#include "support/fixtures.h"

using namespace facetlight;

namespace {

TraceSettings stoneOf(const std::string& material, double axisTiltDeg, double axisAzimuthDeg = 0) {
    TraceSettings s;
    s.material = material;
    s.opticAxis.tiltDeg = axisTiltDeg;
    s.opticAxis.azimuthDeg = axisAzimuthDeg;
    s.threads = 2;
    return s;
}

// The walk-off of the extraordinary ray from the wave normal, at angle theta to the optic axis (Born & Wolf,
// Principles of Optics, sec. 15.3): tan rho = (1 - (n_o/n_e)^2) tan theta / (1 + (n_o/n_e)^2 tan^2 theta).
double walkOff(const std::string& material, double thetaDeg) {
    const std::array<double, 3> n = Material::byName(material).principalIndices(Material::kSodiumD);
    const double r = (n[0] / n[2]) * (n[0] / n[2]), t = std::tan(radians(thetaDeg));
    return std::atan(std::abs((1 - r) * t / (1 + r * t * t)));
}

}  // namespace

TEST(Doubling, SlabLookedAtAlongItsNormalDoublesByItsThicknessTimesTheWalkOff) {
    // The unit cube at 6.5 mm is a slab 6.5 mm thick; seen along its normal the ordinary ray goes straight
    // down and the extraordinary one walks off by rho, so the two images of a point on the bottom are
    // L tan(rho) apart, the same everywhere (calcite at 44.6 deg: rho 6.24 deg, 0.711 mm with the
    // fit's 1.6583 and 1.4861).
    for (const auto& [material, theta] : std::vector<std::pair<std::string, double>>{{"calcite", 44.6},
                                                                                     {"calcite", 20},
                                                                                     {"calcite", 70},
                                                                                     {"moissanite", 45},
                                                                                     {"zircon", 30},
                                                                                     {"quartz", 60},
                                                                                     {"sapphire", 50}}) {
        const Doubling d = doubling(test::unitCube(), stoneOf(material, theta, 30), {64});
        const double expected = 6.5 * std::tan(walkOff(material, theta));
        ASSERT_TRUE(d.doublyRefracting) << material;
        EXPECT_GT(d.table.pixels, 1000u) << material;
        EXPECT_NEAR(d.table.medianMm, expected, 1e-4 * expected + 1e-6) << material << " " << theta;
        EXPECT_NEAR(d.table.lowMm, d.table.highMm, 1e-4 * expected + 1e-6) << material << " " << theta;
        EXPECT_NEAR(d.viewToAxisDeg, theta, 1e-9);
    }
    EXPECT_NEAR(6.5 * std::tan(walkOff("calcite", 44.6)), 0.711, 0.001);
}

TEST(Doubling, AWedgeDoublesByTheImagesNotByTheRaysHits) {
    // A wedge: the bottom flat, the top rising along y at alpha, seen from above, the axis in the y-z plane
    // so that both rays stay in it. A ray entering at image height y goes down a depth D(y) and moves across
    // by s D (s = r_y / -r_z of its ray r): the pavilion point the ordinary ray of y meets is seen through
    // the extraordinary wave at y' with y' + s_e D(y') = y + s_o D(y), D(y') = D(y) + (y' - y) tan alpha, so
    // the images lie (s_o - s_e) D(y) / (1 + s_e tan alpha) apart: not the rays' own (s_o - s_e) D(y).
    const double alpha = radians(20);
    const Stone wedge = test::hexahedron(
        [&](int i) {
            const double y = (i >> 1) & 1;
            return Vec3{double(i & 1), y, (i >> 2) & 1 ? 1 + y * std::tan(alpha) : 0.0};
        },
        "wedge");
    const TraceSettings s = stoneOf("calcite", 45, 90);
    const Doubling d = doubling(wedge, s, {96});
    const Facet& top = *std::find_if(wedge.facets.begin(), wedge.facets.end(),
                                     [](const Facet& f) { return f.region == Region::Crown; });
    const double tanAlpha = -top.normal.y / top.normal.z;
    ASSERT_NEAR(tanAlpha, std::tan(alpha), 1e-9);
    const std::array<double, 3> n = Material::byName("calcite").principalIndices(Material::kSodiumD);
    const InterfaceWaves w = enterCrystal({n[0], n[2], s.opticAxis.direction()}, {0, 0, -1}, top.normal);
    const Vec3 o = w.transmitted[0].wave.ray, e = w.transmitted[1].wave.ray;
    ASSERT_NEAR(e.x, 0, 1e-12);
    const double so = o.y / -o.z, se = e.y / -e.z;
    // The wedge is 1 across, so 1 unit is size_mm; the picture's centre row is at the wedge's middle, y =
    // 0.5.
    uint64_t checked = 0;
    double largestGap = 0;
    for (int row = 0; row < d.size; ++row) {
        const double y = (1 - 2 * (row + 0.5) / d.size) * d.halfWidthMm;
        const double depth = 6.5 * (1 + 0.5 * tanAlpha) + y * tanAlpha;
        const double expected = std::abs(so - se) * depth / (1 + se * tanAlpha);
        for (int col = 0; col < d.size; ++col) {
            const float got = d.doublingMm[size_t(row) * size_t(d.size) + size_t(col)];
            if (got < 0) continue;
            EXPECT_NEAR(got, expected, 1e-4 * expected) << row << " " << col;
            largestGap = std::max(largestGap, std::abs(std::abs(so - se) * depth - expected));
            ++checked;
        }
    }
    EXPECT_GT(checked, 4000u);
    EXPECT_GT(largestGap, 0.01);  // the images' distance and the rays' differ by more than the tolerance
}

TEST(Doubling, NoneAlongTheAxisAcrossItOrInASinglyRefractingStone) {
    // Along the optic axis the two waves coincide; with the axis in the slab's plane the wave normal is
    // across it and the extraordinary ray does not walk off; diamond gives one image.
    const Doubling along = doubling(test::unitCube(), stoneOf("calcite", 0), {64});
    EXPECT_GT(along.table.pixels, 1000u);
    EXPECT_EQ(along.table.medianMm, 0);
    EXPECT_EQ(along.table.highMm, 0);
    EXPECT_NEAR(doubling(test::unitCube(), stoneOf("calcite", 90), {64}).table.highMm, 0, 1e-6);
    for (const char* material : {"diamond"}) {
        const Doubling d = doubling(test::roundBrilliant(), stoneOf(material, 45), {96});
        EXPECT_FALSE(d.doublyRefracting) << material;
        EXPECT_GT(d.crown.pixels, 3000u) << material;
        EXPECT_EQ(d.crown.highMm, 0) << material;
        EXPECT_EQ(d.viewToAxisDeg, 0) << material;
    }
    EXPECT_NE(
        doubling(test::roundBrilliant(), stoneOf("diamond", 0), {32}).tracedAs.find("singly refracting"),
        std::string::npos);
}

// A biaxial stone splits into its fast and slow waves: peridot (alpha 1.635, gamma 1.670) doubles about as a
// uniaxial stone with the same extreme indices, more than topaz (0.010), and a tenth of a degree from an
// optic axis almost nothing doubles through a slab (the two indices meet there).
TEST(Doubling, BiaxialStonesDoubleByTheirBirefringence) {
    const Doubling peridot = doubling(test::roundBrilliant(), stoneOf("peridot", 45), {128});
    const Doubling topaz = doubling(test::roundBrilliant(), stoneOf("topaz", 45), {128});
    TraceSettings uniaxial = stoneOf("auto", 45);
    MaterialDefinition m;
    m.nO = 1.635;
    m.nE = 1.670;
    m.dispersionBG = 0.020;
    uniaxial.customMaterial = m;
    const Doubling like = doubling(test::roundBrilliant(), uniaxial, {128});
    EXPECT_TRUE(peridot.doublyRefracting);
    EXPECT_NE(peridot.tracedAs.find("biaxial"), std::string::npos);
    EXPECT_NEAR(peridot.nA, 1.635, 1e-3);
    EXPECT_GT(peridot.table.medianMm, 0.005);
    EXPECT_GT(peridot.table.medianMm, 0.3 * like.table.medianMm);
    EXPECT_LT(peridot.table.medianMm, 3 * like.table.medianMm);
    EXPECT_GT(topaz.table.medianMm, 0);
    EXPECT_GT(peridot.table.medianMm, 2 * topaz.table.medianMm);
    EXPECT_EQ(toJson(peridot)["alpha"], peridot.nA);
    EXPECT_FALSE(toJson(like).contains("alpha"));
    // Rotating X and Y about Z changes what the view meets.
    TraceSettings turned = stoneOf("peridot", 45);
    turned.opticAxis.rotationDeg = 90;
    EXPECT_NE(doubling(test::roundBrilliant(), turned, {128}).table.medianMm, peridot.table.medianMm);

    // A cube looked at along Z, a principal axis: both waves' fields lie along principal axes and neither ray
    // walks off, so nothing doubles. Along an optic axis the indices meet but the rays do not: a wave normal
    // there has a cone of rays (internal conical refraction) of angle chi, tan chi = beta^2 sqrt((1/alpha^2 -
    // 1/beta^2)(1/beta^2 - 1/gamma^2)) (Born & Wolf sec. 15.3.4), and the two waves take opposite sides of
    // it: the images lie L tan chi apart, 1.21 deg for peridot.
    EXPECT_NEAR(doubling(test::unitCube(), stoneOf("peridot", 0), {64}).table.highMm, 0, 1e-9);
    const BiaxialMedium crystal{1.635, 1.651, 1.670, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double vz = degrees(std::acos(dot(opticAxes(crystal)[0], Vec3{0, 0, 1})));
    const Doubling onAxis = doubling(test::unitCube(), stoneOf("peridot", vz, 180), {64});
    const std::array<double, 3> n = Material::byName("peridot").principalIndices(Material::kSodiumD);
    const double ua = 1 / (n[0] * n[0]), ub = 1 / (n[1] * n[1]), ug = 1 / (n[2] * n[2]);
    const double tanChi = std::sqrt((ua - ub) * (ub - ug)) / ub;
    EXPECT_LT(onAxis.viewToAxisDeg, 0.05);
    EXPECT_GT(onAxis.table.pixels, 1000u);
    EXPECT_NEAR(onAxis.table.medianMm, onAxis.sizeMm * tanChi, 0.01 * onAxis.sizeMm * tanChi);
}

TEST(Doubling, BiaxialSameNumbersAtAnyThreadCount) {
    TraceSettings one = stoneOf("peridot", 60, 20), three = one;
    one.opticAxis.rotationDeg = 30;
    three.opticAxis.rotationDeg = 30;
    one.threads = 1;
    three.threads = 3;
    const Doubling a = doubling(test::roundBrilliant(), one, {80}),
                   b = doubling(test::roundBrilliant(), three, {80});
    EXPECT_EQ(a.doublingMm, b.doublingMm);
    EXPECT_EQ(toJson(a).dump(), toJson(b).dump());
}

TEST(Doubling, OnTheBrilliantZirconDoublesMoreThanMoissaniteMoreThanQuartz) {
    // The same cut, the axis 45 deg from the table's normal: the walk-off goes with (n_e^2 - n_o^2) / n^2,
    // zircon's 0.059 of 1.95 above moissanite's 0.042 of 2.65 above quartz's 0.009 of 1.55.
    const Doubling zircon = doubling(test::roundBrilliant(), stoneOf("zircon", 45), {128});
    const Doubling moissanite = doubling(test::roundBrilliant(), stoneOf("moissanite", 45), {128});
    const Doubling quartz = doubling(test::roundBrilliant(), stoneOf("quartz", 45), {128});
    EXPECT_GT(quartz.table.medianMm, 0.005);
    EXPECT_GT(moissanite.table.medianMm, 1.5 * quartz.table.medianMm);
    EXPECT_GT(zircon.table.medianMm, 1.5 * moissanite.table.medianMm);
    EXPECT_GT(zircon.crown.medianMm, moissanite.crown.medianMm);
    EXPECT_GT(moissanite.crown.medianMm, quartz.crown.medianMm);
    // Moissanite cut with its axis along the table's normal (as it usually is): nothing doubles through the
    // table, seen along the axis, while the bezels, seen at an angle to it, still double.
    const Doubling cut = doubling(test::roundBrilliant(), stoneOf("moissanite", 0), {128});
    EXPECT_GT(cut.table.pixels, 3000u);
    EXPECT_EQ(cut.table.highMm, 0);
    EXPECT_GT(cut.crown.highMm, 0.01);
    // Tilting the stone toward its axis brings the doubling through the table up from nothing.
    DoublingSettings tilted{128};
    tilted.tiltDeg = 30;
    EXPECT_GT(doubling(test::roundBrilliant(), stoneOf("moissanite", 0), tilted).table.medianMm, 0.01);
}

TEST(Doubling, SameNumbersAtAnyThreadCount) {
    TraceSettings one = stoneOf("moissanite", 60, 20), three = one;
    one.threads = 1;
    three.threads = 3;
    const Doubling a = doubling(test::roundBrilliant(), one, {80}),
                   b = doubling(test::roundBrilliant(), three, {80});
    EXPECT_EQ(a.doublingMm, b.doublingMm);
    EXPECT_EQ(a.ordinary, b.ordinary);
    EXPECT_EQ(a.extraordinary, b.extraordinary);
    EXPECT_EQ(toJson(a).dump(), toJson(b).dump());
}

TEST(Doubling, RefusesSettingsOutOfRangeNamingTheField) {
    test::expectError([] { doubling(test::roundBrilliant(), stoneOf("zircon", 45), {8}); }, "picture_size");
    DoublingSettings d;
    d.loupe = 0;
    test::expectError([&] { doubling(test::roundBrilliant(), stoneOf("zircon", 45), d); }, "loupe");
}

TEST(Doubling, PictureShowsBothImagesWithTitleAndScale) {
    const Doubling d = doubling(test::roundBrilliant(), stoneOf("zircon", 45), {120});
    const Image image = doublingPicture(d, "zircon");
    EXPECT_GT(image.width(), 120);
    EXPECT_GT(image.height(), 120);
    // Both wave's edge colours appear, apart from each other where the stone doubles.
    int ordinary = 0, extraordinary = 0;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const Rgb& c = image.at(x, y);
            ordinary += c.b > 0.6f && c.r < 0.3f;
            extraordinary += c.r > 0.7f && c.b < 0.3f;
        }
    EXPECT_GT(ordinary, 200);
    EXPECT_GT(extraordinary, 200);
}

TEST(Doubling, AJobAsksForItAndGetsItsStatisticsAndPicture) {
    // A job's `doubling` (docs/stats-schema.md): run after the trace, counted in the viewing phase.
    const JobRequest spec = JobRequest::fromJson({{"mesh", "round_brilliant"},
                                                  {"material", "moissanite"},
                                                  {"optic_axis", {{"tilt_deg", 45}}},
                                                  {"photons", 2000},
                                                  {"viewer", {{"enabled", false}}},
                                                  {"doubling", {{"picture_size", 64}, {"loupe", 5}}}});
    ASSERT_TRUE(spec.settings.doubling);
    EXPECT_EQ(studyUnits(spec.settings, RunPhase::Viewing), 64u * 64u);
    RunControl control;
    const StudyResult r = runStudy(test::roundBrilliant(), spec.settings, control);
    ASSERT_TRUE(r.stats.contains("doubling"));
    const nlohmann::json& d = r.stats["doubling"];
    EXPECT_TRUE(d["doubly_refracting"].get<bool>());
    EXPECT_GT(d["table"]["median_mm"].get<double>(), 0.02);
    EXPECT_EQ(d["loupe"], 5);
    EXPECT_EQ(r.file("doubling.png").substr(1, 3), "PNG");
    EXPECT_EQ(control.done(), control.total());
    test::expectError(
        [] {
            JobRequest::fromJson({{"mesh", "round_brilliant"}, {"doubling", {{"tilt_deg", 90}}}});
        },
        "doubling.tilt_deg");
}
