#include "viewer/verdict.h"

#include <gtest/gtest.h>

#include <cmath>

#include "cuts/cut_library.h"
#include "optics/material.h"
#include "stone/stone.h"
#include "support/fixtures.h"
#include "util/error.h"
#include "viewer/spot_fire.h"
#include "viewer/viewer_figures.h"

using namespace facetlight;

namespace {

// Unpolarised Fresnel reflectance from air into index n at incidence `theta` (optics.md), with Snell's law.
double reflectance(double n, double theta) {
    const double ci = std::cos(theta), ct = std::sqrt(1 - std::pow(std::sin(theta) / n, 2));
    const double rs = (ci - n * ct) / (ci + n * ct), rp = (ct - n * ci) / (ct + n * ci);
    return (rs * rs + rp * rp) / 2;
}

TraceSettings diamondWithoutDispersion() {
    TraceSettings s;
    s.dispersion = false;
    return s;
}

Stone cut(const std::string& shape, const CutValues& values) {
    return Stone::build(makeCut(shape, values), shape);
}

ViewerFigure measure(const ViewerFigures& f, std::string_view fault) {
    for (const FaultRule& rule : kFaultRules)
        if (rule.key == fault) return (f.*rule.measure)();
    ADD_FAILURE() << "no fault " << fault;
    return {};
}

}  // namespace

// A wide diamond slab seen from the viewer's eye straight above, at one tilt: each view ray reflects off the
// top with R or crosses, and each crossing it leaves through the bottom (the tray) with 1 - R or comes back
// up with R and leaves through the top, parallel to the first reflection, with 1 - R. Summed: 2R / (1 + R) of
// the face-up area shows the mirror direction and (1 - R) / (1 + R) the tray, R the Fresnel reflectance at
// the tilt. Face-up the mirror direction is the viewer's head (dark); tilted 30 deg it is the dome at 30 deg
// elevation, of radiance sin 30 deg = 0.5 under the cosine dome. The tray (albedo a) has radiance
// a E / pi = 2a / 3 under it.
TEST(OfficeView, SlabShowsItsMirrorDirectionAndTheTrayByFresnel) {
    const Stone slab = test::box(1000, 1000, 1);  // wide: few rays meet its sides
    const double n = Material::byName("diamond").indexD();
    for (const double tiltDeg : {0.0, 30.0}) {
        TraceSettings s = diamondWithoutDispersion();
        s.viewer.shoulderWidthMm = 0;  // nothing but the head: the mirror direction at 30 deg meets the dome
        s.viewer.rockDeg = tiltDeg;
        s.viewer.tilts = tiltDeg > 0 ? 2 : 1;  // -30 and +30: the same slab, mirrored
        s.viewer.azimuths = 1;
        s.viewer.sparkleStepDeg = 1e-6;  // the twin looks: the same as the first within rounding
        s.viewer.office.points = 20000;
        const ViewerFigures f = viewStone(slab, s);
        const double r = reflectance(n, radians(tiltDeg));
        const double mirror = 2 * r / (1 + r), tray = (1 - r) / (1 + r);
        const double sky = tiltDeg > 0 ? mirror : 0.0, head = tiltDeg > 0 ? 0.0 : mirror;
        const double brightness = sky * std::sin(radians(90 - 2 * tiltDeg)) + tray * 0.18 * 2 / 3;
        EXPECT_NEAR(f.contrast().value, head, 4 * f.contrast().stderr + 1e-9) << "tilt " << tiltDeg;
        EXPECT_NEAR(f.windowing().value, tray, 4 * f.windowing().stderr) << "tilt " << tiltDeg;
        EXPECT_NEAR(f.brightness().value, brightness, 4 * f.brightness().stderr + 1e-9) << "tilt " << tiltDeg;
        EXPECT_GT(f.office.rays, 10000u);
    }
}

// The figures are integer tallies over points that draw from their own streams: the same bits for any number
// of threads.
TEST(ViewerFigures, SameBitsForAnyThreadCount) {
    TraceSettings s;
    s.viewer.office.points = 2000;
    s.viewer.spot.photons = 20000;
    s.threads = 1;
    const ViewerFigures one = viewStone(test::roundBrilliant(), s);
    s.threads = 3;
    const ViewerFigures three = viewStone(test::roundBrilliant(), s);
    EXPECT_EQ(one.office, three.office);
    EXPECT_EQ(one.spot, three.spot);
    EXPECT_GT(one.spot.coloured, 0u);
}

// Without dispersion every band takes one path: no photon is seen as colour.
TEST(SpotFire, NoDispersionNoFire) {
    TraceSettings s = diamondWithoutDispersion();
    s.viewer.spot.photons = 20000;
    const ViewerFigures f = viewStone(test::roundBrilliant(), s);
    EXPECT_GT(f.spot.pairs, 1000u);
    EXPECT_EQ(f.spot.coloured, 0u);
    EXPECT_EQ(f.fire().value, 0.0);
}

// A lamp behind the viewer's head or shoulders lights nothing; with every lamp there, the settings are
// refused.
TEST(SpotFire, LampsTheViewerHidesAreLeftOut) {
    ViewerSettings v;
    // At azimuths 30, 90, ..., 330 deg, 50 deg up: the shoulders, 40.6 deg from the zenith toward -y (azimuth
    // 270) and 25.7 deg in radius, hide the lamp at 270 alone (those at 210 and 330 are 38 deg from their
    // centre).
    v.spot.lamps = 6;
    EXPECT_EQ(spotLamps(v).size(), 5u);
    v.spot.elevationDeg = 85;  // all within the head's disc around the zenith
    try {
        spotLamps(v);
        FAIL() << "no lamp is left";
    } catch (const Error& e) {
        EXPECT_EQ(e.field(), "viewer.spot.lamps");
    }
}

// The reference judged against itself: every difference exactly 0 (the same stone draws the same numbers), no
// fault, the score 100.
TEST(Verdict, TheReferenceMatchesItselfAndHasNoFault) {
    TraceSettings s;
    s.viewer.office.points = 4000;
    s.viewer.spot.photons = 100000;
    const ViewerFigures& reference = referenceFigures(s);
    const Stone stone = cut("round_brilliant", {});
    const Verdict v = judge(stone, viewStone(stone, s), reference);
    for (const FigureComparison& c : v.figures) EXPECT_EQ(c.difference.value, 0.0) << c.info->key;
    for (const FaultFinding& f : v.faults) EXPECT_FALSE(f.present) << f.text;
    EXPECT_DOUBLE_EQ(v.score.value, 100.0);
    double weights = 0;
    for (const ScoreWeight& w : kScoreWeights) weights += w.weight;
    EXPECT_DOUBLE_EQ(weights, 1.0);
}

// Each fault on stones known to show it, beside the GIA reference, which shows none: the measure above its
// threshold by several standard errors on the one, below it on the other.
TEST(Verdict, FaultsAreFoundOnStonesKnownToShowThem) {
    TraceSettings s;
    s.viewer.office.points = 6000;
    s.viewer.spot.photons = 1000;
    TraceSettings glass = s;
    glass.material = "bk7";
    const struct {
        std::string fault, shape;
        CutValues values;
        const TraceSettings& settings;
    } cases[] = {
        {"fish_eye", "round_brilliant", {{"pavilion", 38}}, s},     // a shallow pavilion (the stones)
        {"nail_head", "round_brilliant", {{"pavilion", 43.5}}, s},  // a deep one
        {"bow_tie", "oval", {{"ratio", 1.7}}, s},
        {"windowing", "round_brilliant", {{"pavilion", 38}}, glass},  // below glass's critical angle
        {"extinction", "round_brilliant", {{"pavilion", 34}}, glass},
    };
    const ViewerFigures reference = viewStone(cut("round_brilliant", {}), s);
    for (const auto& c : cases) {
        const Stone stone = cut(c.shape, c.values);
        const ViewerFigures f = viewStone(stone, c.settings);
        const Verdict v = judge(stone, f, reference);
        const ViewerFigure shown = measure(f, c.fault), none = measure(reference, c.fault);
        double threshold = 0;
        bool present = false;
        for (const FaultFinding& finding : v.faults)
            if (finding.rule->key == c.fault) threshold = finding.rule->threshold, present = finding.present;
        EXPECT_TRUE(present) << c.fault;
        EXPECT_GT(shown.value - 3 * shown.stderr, threshold) << c.fault;
        EXPECT_LT(none.value + 3 * none.stderr, threshold) << c.fault << " on the reference";
    }
}

// The bow-tie is looked for on elongated stones only: the round's middle slice is the table's centre.
TEST(Verdict, BowTieOnlyOnElongatedStones) {
    TraceSettings s;
    s.viewer.office.points = 2000;
    s.viewer.spot.photons = 1000;
    const Stone round = cut("round_brilliant", {{"pavilion", 44.5}});
    const ViewerFigures f = viewStone(round, s);
    const Verdict v = judge(round, f, f);
    for (const FaultFinding& finding : v.faults)
        if (finding.rule->key == "bow_tie") {
            EXPECT_FALSE(finding.applies);
        }
}

TEST(ViewerSettings, RefusedSettingsNameTheirField) {
    nlohmann::json j = toJson(ViewerSettings{});
    j["tilts"] = 1;
    try {
        ViewerSettings::fromJson(j);
        FAIL() << "a rock of one tilt";
    } catch (const Error& e) {
        EXPECT_EQ(e.field(), "viewer.tilts");
    }
    j = toJson(ViewerSettings{});
    j["office"]["dome"] = "sunny";
    EXPECT_THROW(ViewerSettings::fromJson(j), Error);
    j = toJson(ViewerSettings{});
    j["spot"]["photons"] = 10;
    try {
        ViewerSettings::fromJson(j);
        FAIL() << "too few photons";
    } catch (const Error& e) {
        EXPECT_EQ(e.field(), "viewer.spot.photons");
    }
}
