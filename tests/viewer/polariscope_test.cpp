#include "viewer/polariscope.h"

#include "pictures/polariscope_chart.h"
#include "study/job_request.h"
#include "study/study.h"

#include <gtest/gtest.h>

#include <cmath>

#include "stone/stone.h"
#include "support/expect_error.h"
#include "support/fixtures.h"

using namespace facetlight;

namespace {

TraceSettings block(const std::string& material, double axisTiltDeg) {
    TraceSettings s;
    s.material = material;
    s.dispersion = false;
    s.opticAxis.tiltDeg = axisTiltDeg;
    s.threads = 2;
    return s;
}

}  // namespace

TEST(Polariscope, IsotropicCubeStaysDarkAtEveryTurn) {
    const Polariscope p = polariscope(test::unitCube(), block("diamond", 0), {12, 4000});
    ASSERT_EQ(p.readings.size(), 12u);
    for (const PolariscopeReading& r : p.readings) {
        EXPECT_GT(r.upward, 1500u);
        EXPECT_EQ(r.passed, 0u) << r.angleDeg << " deg";
    }
    EXPECT_EQ(p.reaction, PolariscopeReaction::StaysDark);
    EXPECT_TRUE(p.darkAnglesDeg.empty());
}

TEST(Polariscope, FacetedStonesStayLightWhetherSinglyOrDoublyRefracting) {
    // A brilliant's total internal reflections retard p against s and turn the polarisation (docs/optics.md):
    // a diamond passes a steady share far above the dark field's, and so does a sapphire seen along its axis,
    // so the verdict is neither "stays dark" nor a blink.
    for (const char* material : {"diamond", "sapphire"}) {
        const Polariscope p = polariscope(test::roundBrilliant(), block(material, 0), {8, 3000});
        EXPECT_EQ(p.reaction, PolariscopeReaction::StaysLight) << material;
        for (const PolariscopeReading& r : p.readings) EXPECT_GT(r.share(), 0.2) << material << r.angleDeg;
    }
}

TEST(Polariscope, SlabCutAlongItsAxisBlinksFourTimesATurn) {
    // Calcite with its optic axis along x, in the plane of the faces: dark where the polariser lies along the
    // axis or across it (the stone turned 0, 90, 180 and 270 deg), brightest between, where the analyser
    // passes sin^2(2 angle) / 2 of the light (Hecht, Optics, sec. 8.10).
    const Polariscope p = polariscope(test::unitCube(), block("calcite", 90), {16, 4000});
    EXPECT_TRUE(p.blinks());
    ASSERT_EQ(p.darkAnglesDeg.size(), 4u);
    EXPECT_EQ(p.darkAnglesDeg[0], 0);
    EXPECT_EQ(p.darkAnglesDeg[1], 90);
    EXPECT_EQ(p.darkAnglesDeg[2], 180);
    EXPECT_EQ(p.darkAnglesDeg[3], 270);
    for (const PolariscopeReading& r : p.readings) {
        const double expected = 0.5 * std::pow(std::sin(2 * radians(r.angleDeg)), 2);
        EXPECT_NEAR(r.share(), expected, 4 * r.shareStderr() + 0.02) << r.angleDeg << " deg";
    }
    // Cut across its axis (seen along it) the block stays dark as it turns: the two waves keep in step.
    const Polariscope along = polariscope(test::unitCube(), block("calcite", 0), {8, 2000});
    EXPECT_EQ(along.reaction, PolariscopeReaction::StaysDark);
    for (const PolariscopeReading& r : along.readings) EXPECT_EQ(r.passed, 0u) << r.angleDeg;
}

TEST(Polariscope, NoisyReadingsStillGoDarkFourTimesATurn) {
    // Many positions of few photons each: the noise makes local minima all along the dips, but a stone's dark
    // positions lie 90 deg apart (its waves vibrate at right angles), one in each dip.
    const Polariscope p = polariscope(test::roundBrilliant(), block("sapphire", 90), {360, 300, 0});
    EXPECT_TRUE(p.blinks());
    ASSERT_EQ(p.darkAnglesDeg.size(), 4u);
    for (size_t k = 0; k < 4; ++k) EXPECT_NEAR(p.darkAnglesDeg[k], 90.0 * double(k), 15) << k;
}

TEST(Polariscope, ABrilliantGoesDarkEveryQuarterTurnThoughNotAlwaysAsDeep) {
    // Zircon with its axis 45 deg from the table's normal: 19.9 % at 0 deg and 18.5 % at 90 deg, 39 %
    // between. Both are dark positions, though 0 deg's reading is not quite under half the brightest.
    TraceSettings s = block("zircon", 45);
    const Polariscope p = polariscope(test::roundBrilliant(), s, {12, 5000, 0});
    EXPECT_TRUE(p.blinks());
    EXPECT_EQ(p.darkAnglesDeg, (std::vector<double>{0, 90, 180, 270}));
}

TEST(Polariscope, BiaxialPlateGoesDarkWhereItsAxesMeetThePolarisers) {
    // Topaz with its Z axis up the light and its X turned 45 deg from the stone's x: the waves down Z vibrate
    // along X and Y, so the plate goes dark where the polarisers lie along them (the stone turned 45, 135,
    // 225 and 315 deg, whichever way it turns) and passes sin^2(2 (angle - 45)) / 2 between; turned 0 (X
    // along x) the dark angles move to 0, 90, 180 and 270 deg.
    TraceSettings s = block("topaz", 0);
    s.polarization = PolarizationMode::On;
    s.opticAxis.rotationDeg = 45;
    const Polariscope p = polariscope(test::unitCube(), s, {8, 3000});
    EXPECT_TRUE(p.blinks());
    EXPECT_EQ(p.darkAnglesDeg, (std::vector<double>{45, 135, 225, 315}));
    for (const PolariscopeReading& r : p.readings) {
        const double expected = 0.5 * std::pow(std::sin(2 * radians(r.angleDeg - 45)), 2);
        EXPECT_NEAR(r.share(), expected, 4 * r.shareStderr() + 0.02) << r.angleDeg << " deg";
    }
    s.opticAxis.rotationDeg = 0;
    EXPECT_EQ(polariscope(test::unitCube(), s, {8, 2000}).darkAnglesDeg,
              (std::vector<double>{0, 90, 180, 270}));
}

TEST(Polariscope, UnderADiffuseLampTheSlabStillBlinksAndAnIsotropicCubeStaysNearlyDark) {
    // A light box: light from every direction below, of which the eye takes what leaves within 15 deg of the
    // vertical. The calcite block with its axis along x still goes dark where the polariser lies along or
    // across the axis (its mirror symmetry makes those angles extremes) and bright between.
    PolariscopeSettings lamp{16, 20000};
    lamp.lamp = PolariscopeLamp::Diffuse;
    const Polariscope slab = polariscope(test::unitCube(), block("calcite", 90), lamp);
    EXPECT_TRUE(slab.blinks());
    EXPECT_EQ(slab.darkAnglesDeg, (std::vector<double>{0, 90, 180, 270}));
    EXPECT_GT(slab.readings[4].share(), 0.35);  // 45 deg
    // An isotropic cube passes a little light between crossed filters (an oblique ray's s and p parts cross
    // its faces unequally, which turns its plane of polarisation; none under the parallel beam, above), does
    // not blink, and its symmetry gives the same share at a turn a and 90 - a.
    const Polariscope cube = polariscope(test::unitCube(), block("diamond", 0), lamp);
    EXPECT_EQ(cube.reaction, PolariscopeReaction::StaysDark);
    uint64_t passed = 0;
    for (const PolariscopeReading& r : cube.readings) {
        passed += r.passed;
        EXPECT_LT(r.share(), 0.1) << r.angleDeg;
    }
    EXPECT_GT(passed, 0u);
    for (size_t k = 1; k < 8; ++k) {
        const PolariscopeReading &a = cube.readings[k], &b = cube.readings[8 - k];
        EXPECT_NEAR(a.share(), b.share(), 4 * std::hypot(a.shareStderr(), b.shareStderr()) + 0.01)
            << a.angleDeg;
    }
}

TEST(Polariscope, PicturesShowTheLightWhereItLeavesAndBlinkWithIt) {
    // The calcite block from above: every passed photon is in its position's picture, on the block's top face
    // turned with the stone, and the frames share one grey scale: dark at 0 deg, lit at 45.
    const Polariscope p = polariscope(test::unitCube(), block("calcite", 90), {4, 4000, 40});
    for (const PolariscopeReading& r : p.readings) {
        ASSERT_EQ(r.seen.size(), 40u * 40u);
        // A cell's centre in the stone's frame: the picture spans 1.05 times the half-diagonal either way, row 0
        // at +y, and shows the stone turned by the reading's angle; the top face spans +-0.5.
        const double half = 1.05 * std::sqrt(0.5), cell = 2 * half / 40, a = radians(r.angleDeg);
        uint64_t seen = 0, outside = 0;
        for (int y = 0; y < 40; ++y)
            for (int x = 0; x < 40; ++x) {
                const uint32_t c = r.seen[size_t(y) * 40 + size_t(x)];
                seen += c;
                const double u = (x + 0.5) * cell - half, v = half - (y + 0.5) * cell;
                const double xs = std::cos(a) * u + std::sin(a) * v, ys = -std::sin(a) * u + std::cos(a) * v;
                if (std::max(std::abs(xs), std::abs(ys)) > 0.5 + cell) outside += c;
            }
        EXPECT_EQ(seen, r.passed) << r.angleDeg;
        EXPECT_EQ(outside, 0u) << r.angleDeg;
    }
    const std::vector<Image> frames = polariscopeFrames(p);
    ASSERT_EQ(frames.size(), 4u);
    // A 40-cell grid drawn in blocks of 4 pixels, so that the label above fits.
    EXPECT_EQ(frames[0].width(), 160);
    EXPECT_EQ(frames[0].height(), 160 + 24);
    auto centre = [&](const Image& f) { return f.at(80, 80 + 24).r; };
    EXPECT_EQ(centre(frames[0]), 0.0f);
    EXPECT_GT(centre(frames[1]), 0.5f);
}

TEST(Polariscope, SameReadingsAtAnyThreadCount) {
    TraceSettings s = block("sapphire", 40);
    const Stone& stone = test::roundBrilliant();
    s.threads = 1;
    const nlohmann::json one = toJson(polariscope(stone, s, {6, 1000}));
    s.threads = 3;
    EXPECT_EQ(toJson(polariscope(stone, s, {6, 1000})).dump(), one.dump());
}

TEST(Polariscope, RefusesSettingsOutOfRange) {
    test::expectError([] { polariscope(test::unitCube(), block("diamond", 0), {2, 1000}); }, "angles");
    test::expectError([] { polariscope(test::unitCube(), block("diamond", 0), {8, 10}); }, "photons");
}

TEST(Polariscope, AJobAsksForItAndGetsItsStatisticsAndFiles) {
    // A job's `polariscope` (docs/stats-schema.md): run after the trace, counted in the viewing phase.
    const JobRequest spec = JobRequest::fromJson({{"mesh", "round_brilliant"},
                                                  {"material", "zircon"},
                                                  {"optic_axis", {{"tilt_deg", 90}}},
                                                  {"photons", 2000},
                                                  {"viewer", {{"enabled", false}}},
                                                  {"polariscope", {{"angles", 8}, {"photons", 2000}, {"picture_size", 32}}}});
    ASSERT_TRUE(spec.settings.polariscope);
    EXPECT_EQ(studyUnits(spec.settings, RunPhase::Viewing), 8u * 2000u);
    RunControl control;
    const StudyResult r = runStudy(test::roundBrilliant(), spec.settings, control);
    ASSERT_TRUE(r.stats.contains("polariscope"));
    EXPECT_EQ(r.stats["polariscope"]["readings"].size(), 8u);
    EXPECT_TRUE(r.stats["polariscope"]["blinks"].get<bool>());
    EXPECT_EQ(r.stats["polariscope"]["reaction"], "blinks");
    EXPECT_EQ(r.file("polariscope.png").substr(1, 3), "PNG");
    EXPECT_EQ(r.file("polariscope.webp").substr(8, 4), "WEBP");
    EXPECT_EQ(control.done(), control.total());
    test::expectError([] { JobRequest::fromJson({{"mesh", "round_brilliant"}, {"polariscope", {{"angles", 2}}}}); },
                      "polariscope.angles");
}
