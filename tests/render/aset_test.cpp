#include "render/aset.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/material.h"
#include "pictures/aset_picture.h"
#include "scene/scene.h"
#include "stone/stone.h"
#include "support/fixtures.h"
#include "util/error.h"

using namespace facetlight;

namespace {

TraceSettings diamond() {
    TraceSettings s;
    s.material = "diamond";
    s.dispersion = false;
    return s;
}

// Fresnel reflectances (s, p) from air into index n at incidence `theta` (optics.md), with Snell's law.
std::pair<double, double> reflectances(double n, double theta) {
    const double ci = std::cos(theta), ct = std::sqrt(1 - std::pow(std::sin(theta) / n, 2));
    const double rs = (ci - n * ct) / (ci + n * ct), rp = (ct - n * ci) / (ct + n * ci);
    return {rs * rs, rp * rp};
}

double share(const AsetView& v, AsetClass c) {
    return v.share(c).share;
}

}  // namespace

// A wide slab seen from far above along one direction: every view ray either reflects off the top or
// crosses, and each crossing it leaves through the bottom (leakage) with 1 - R or comes back up with R, where
// it leaves through the top, parallel to the first reflection, with 1 - R. Summed: 2R / (1 + R) of the rays
// show the sky in the mirror direction and (1 - R) / (1 + R) leak, R the Fresnel reflectance at the view's
// incidence. Unpolarised, R is the mean of Rs and Rp; polarised, the s and p parts never mix between the
// slab's parallel faces, so the share is the mean of each part's own 2R / (1 + R). Face-up the mirror
// direction is the viewer's head; at 60 deg elevation bright light, at 30 deg low light.
TEST(AsetView, SlabShowsItsMirrorDirectionByFresnelAndSnell) {
    const Stone slab = test::box(20, 20, 1);
    const double n = Material::byName("diamond").indexD();
    const struct {
        double elevation;
        AsetClass mirror;
    } views[] = {{90, AsetClass::Head}, {60, AsetClass::Bright}, {30, AsetClass::Low}};
    for (const PolarizationMode mode : {PolarizationMode::Off, PolarizationMode::On}) {
        TraceSettings settings = diamond();
        settings.polarization = mode;
        const Scene scene(slab, settings);
        const TraceBase trace(scene, settings);
        for (const auto& v : views) {
            CameraSettings camera;
            camera.elevationDeg = v.elevation;
            camera.distance =
                10;  // 200 slab thicknesses away, 2 deg wide: the rays within 1 deg of each other
            camera.fovDeg = 2;
            AsetSettings aset;
            aset.samples = 16;
            const AsetView view = asetView(trace, camera, 48, 48, aset, 2, 11);
            ASSERT_EQ(view.stoneRays(), 48u * 48u * 16u) << "every ray meets the slab";
            const auto [rs, rp] = reflectances(n, radians(90 - v.elevation));
            const auto mirrored = [](double r) { return 2 * r / (1 + r); };
            const double expected =
                mode == PolarizationMode::Off ? mirrored((rs + rp) / 2) : (mirrored(rs) + mirrored(rp)) / 2;
            const AsetShare mirror = view.share(v.mirror);
            const std::string where =
                std::string(kPolarizationNames.name(mode)) + " at " + std::to_string(v.elevation) + " deg";
            EXPECT_NEAR(mirror.share, expected, 4 * mirror.standardError + 1e-3) << where;
            EXPECT_NEAR(share(view, AsetClass::Leakage), 1 - expected, 4 * mirror.standardError + 1e-3)
                << where;
            EXPECT_NEAR(mirror.share + share(view, AsetClass::Leakage), 1.0, 1e-12);
        }
    }
}

// A unit cube face-up under the default camera: its top face fills (1 / (2 * 3.5 * tan 10 deg))^2 of the
// picture (the top is 3.5 diameters from the camera, the field 20 deg), and nearly vertical rays go out
// through the bottom: (1 - R) / (1 + R) leak, at normal incidence R = 0.1720 (optics.md).
TEST(AsetView, CubeLeaksThroughItsBottom) {
    const Stone cube = test::box(1, 1, 1);
    const Scene scene(cube, diamond());
    const TraceBase trace(scene, diamond());
    AsetSettings settings;
    settings.samples = 8;
    const int side = 120;
    const AsetView view = asetView(trace, CameraSettings{}, side, side, settings, 2, 3);
    const double area = std::pow(1 / (2 * 3.5 * std::tan(radians(10))), 2);
    EXPECT_NEAR(double(view.stoneRays()) / (side * side * settings.samples), area, 0.01);
    const double r = 0.1720;  // s and p alike at normal incidence: polarised or not
    const AsetShare leakage = view.share(AsetClass::Leakage);
    EXPECT_NEAR(leakage.share, (1 - r) / (1 + r), 4 * leakage.standardError + 1e-3);
    EXPECT_NEAR(share(view, AsetClass::Head), 2 * r / (1 + r), 4 * leakage.standardError + 1e-3);
    EXPECT_EQ(view.totals[size_t(AsetClass::Bright)] + view.totals[size_t(AsetClass::Low)], 0u);
}

TEST(AsetView, SameBitsForAnyThreadCount) {
    const Scene scene(test::roundBrilliant(), diamond());
    const TraceBase trace(scene, diamond());
    AsetSettings settings;
    settings.samples = 4;
    const AsetView one = asetView(trace, CameraSettings{}, 64, 64, settings, 1, 5);
    const AsetView three = asetView(trace, CameraSettings{}, 64, 64, settings, 3, 5);
    EXPECT_EQ(one.counts, three.counts);
    EXPECT_EQ(one.totals, three.totals);
    const AsetView reseeded = asetView(trace, CameraSettings{}, 64, 64, settings, 1, 6);
    EXPECT_NE(one.counts, reseeded.counts);
}

// A round brilliant face-up returns most light from the sky and leaks little; a head cone wider by 25 deg
// turns bright light into head.
TEST(AsetView, BrilliantIsMostlyLitAndTheHeadConeIsASetting) {
    const Scene scene(test::roundBrilliant(), diamond());
    const TraceBase trace(scene, diamond());
    AsetSettings settings;
    settings.samples = 4;
    const AsetView view = asetView(trace, CameraSettings{}, 80, 80, settings, 2, 1);
    EXPECT_GT(share(view, AsetClass::Bright) + share(view, AsetClass::Low), 0.5);
    EXPECT_LT(share(view, AsetClass::Leakage), 0.2);
    settings.headConeDeg = 40;
    const AsetView wide = asetView(trace, CameraSettings{}, 80, 80, settings, 2, 1);
    EXPECT_GT(share(wide, AsetClass::Head), share(view, AsetClass::Head) + 0.05);
    EXPECT_EQ(wide.stoneRays(), view.stoneRays());
}

TEST(AsetView, PictureHasTheViewAndALegend) {
    const Scene scene(test::roundBrilliant(), diamond());
    const TraceBase trace(scene, diamond());
    AsetSettings settings;
    settings.samples = 2;
    const AsetView view = asetView(trace, CameraSettings{}, 64, 64, settings, 1, 1);
    const Image picture = asetPicture(view, settings, "title");
    EXPECT_GE(picture.width(), 64);
    EXPECT_GT(picture.height(), 64 + 5 * 16);
    EXPECT_FALSE(encodePng(picture).empty());
}

TEST(AsetSettings, StrictJson) {
    const AsetSettings s = AsetSettings::fromJson({{"head_cone_deg", 20}, {"samples", 3}});
    EXPECT_EQ(s.headConeDeg, 20);
    EXPECT_EQ(s.samples, 3);
    EXPECT_THROW(AsetSettings::fromJson({{"head_cone", 20}}), Error);
    EXPECT_THROW(AsetSettings::fromJson({{"head_cone_deg", 90}}), Error);
    EXPECT_THROW(AsetSettings::fromJson({{"samples", 0}}), Error);
    EXPECT_THROW(AsetSettings::fromJson({{"low_below_deg", "45"}}), Error);
    const TiltSeriesSettings t = TiltSeriesSettings::fromJson({{"max_deg", 10}});
    EXPECT_EQ(t.frames(), 21);
    EXPECT_EQ(t.tiltDeg(0), -10);
    EXPECT_EQ(t.tiltDeg(20), 10);
    EXPECT_THROW(TiltSeriesSettings::fromJson({{"max_deg", 0}}), Error);
    EXPECT_THROW(TiltSeriesSettings::fromJson({{"max_deg", 10}, {"step_deg", 0.01}}), Error);
}
