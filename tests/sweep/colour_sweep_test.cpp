// A sweep with the colour view (docs/sweeps.md, "Colour"): every point's colour figures, over size, material
// or the cut, equal to a single study's colour view of that design at those settings.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "colour/cie.h"
#include "colour/colour_space.h"
#include "cuts/cut_library.h"
#include "optics/absorption.h"
#include "optics/gem_spectra.h"
#include "optics/material_definition.h"
#include "study/study.h"
#include "sweep/sweep_figures.h"
#include "sweep/sweep_files.h"
#include "sweep/sweep_pictures.h"
#include "sweep/sweep_request.h"
#include "util/error.h"

using namespace facetlight;

namespace {

// A coarse colour view: enough pixels for L* to be known to a few tenths, quick enough for a test.
ColourSettings coarseColour() {
    ColourSettings c;
    c.pictureSize = 24;
    c.samples = 1;
    c.wavelengths = 8;
    return c;
}

TraceSettings quickTrace() {
    TraceSettings t;
    t.photons = 500;
    t.threads = 2;
    t.seed = 7;
    t.viewer.enabled = false;
    return t;
}

SweepRequest requestOf(const std::vector<std::string>& axes, const std::string& figure) {
    SweepRequest r;
    for (const std::string& a : axes) r.axes.push_back(parseSweepAxis(a));
    r.figures = {figure};
    return r;
}

// The field an Error from `f` names; "" when it throws none.
template <class F>
std::string fieldOf(F f) {
    try {
        f();
    } catch (const Error& e) {
        return e.field().empty() ? std::string("(no field)") : e.field();
    }
    return "";
}

}  // namespace

// Over size: the absorbing sapphire darkens at every step by many standard errors, while the clear diamond's
// figures do not move at all (an isotropic stone that does not absorb is scale-free: nothing in its view
// depends on the size; a birefringent one's coherent near-axis cone does).
TEST(ColourSweep, SizeDarkensAnAbsorbingStoneAndLeavesAClearOneAlone) {
    // Enough pixels for a step's drop to stand out against the two points' errors taken as independent.
    ColourSettings colour = coarseColour();
    colour.pictureSize = 48;
    const SweepPlan plan =
        planSweep("round_brilliant",
                  requestOf({"material=blue_sapphire,diamond", "size_mm=3,6,12"}, "colour_lightness"),
                  quickTrace(), colour);
    RunControl control;
    const SweepResult result = runSweep(plan, control);
    ASSERT_EQ(result.points.size(), 6u);
    for (const SweepPoint& p : result.points) ASSERT_TRUE(p.ok()) << p.error;
    const auto at = [&](size_t material, size_t size) -> const SweepPoint& {
        return result.points[material * 3 + size];
    };
    for (size_t s = 0; s + 1 < 3; ++s) {
        const SweepPoint &small = at(0, s), &large = at(0, s + 1);
        const double drop = small.figure("colour_lightness") - large.figure("colour_lightness");
        const double sigma =
            std::hypot(small.stderrOf("colour_lightness"), large.stderrOf("colour_lightness"));
        EXPECT_GT(drop, 3 * sigma) << "sapphire from " << plan.axes[1].label(s) << " mm";
        for (const std::string& f : sweepColourFigureNames())
            EXPECT_EQ(at(1, s).figure(f), at(1, s + 1).figure(f)) << "diamond " << f;
    }
    EXPECT_GT(at(1, 0).figure("colour_lightness"), at(0, 0).figure("colour_lightness"));

    // sweep.json names the figures and the colour settings; sweep.csv has each figure and its error.
    const nlohmann::json j = sweepToJson(result);
    EXPECT_EQ(j["figures"], nlohmann::json(sweepFigureNames(plan.trace, true)));
    EXPECT_EQ(j["colour"]["picture_size"], 48);
    EXPECT_EQ(j["axes"][1]["unit"], "mm");
    const std::string csv = sweepCsv(result);
    for (const std::string& f : sweepColourFigureNames())
        EXPECT_NE(csv.find("," + f + "," + f + "_stderr"), std::string::npos) << f;
    const auto pictures = sweepPictures(result, {"colour_lightness"});
    ASSERT_EQ(pictures.size(), 1u);
    EXPECT_EQ(pictures[0].first, "map_colour_lightness.png");
}

// A point's colour figures are a single study's colour view of its design, bit for bit: the same seed, size
// and material.
TEST(ColourSweep, PointEqualsTheSingleColourView) {
    const SweepPlan plan = planSweep(
        "round_brilliant", requestOf({"pavilion=40,42"}, "colour_chroma"),
        [] {
            TraceSettings t = quickTrace();
            t.material = "emerald";
            t.sizeMm = 8;
            return t;
        }(),
        coarseColour());
    RunControl control;
    const SweepResult result = runSweep(plan, control);
    const SweepPoint& p = result.points[1];
    ASSERT_TRUE(p.ok()) << p.error;

    StudySettings single;
    single.trace = plan.trace;
    single.trace.threads = 1;
    single.colour = coarseColour();
    RunControl alone;
    const StudyResult study =
        runStudy(Stone::build(makeCut("round_brilliant", {{"pavilion", 42}}), "alone"), single, alone);
    const nlohmann::json& c = study.stats.at("colour");
    EXPECT_EQ(p.figure("colour_lightness"), c["L"]["mean"].get<double>());
    EXPECT_EQ(p.stderrOf("colour_lightness"), c["L"]["mean_stderr"].get<double>());
    EXPECT_EQ(p.figure("colour_a"), c["a"]["mean"].get<double>());
    EXPECT_EQ(p.figure("colour_b"), c["b"]["mean"].get<double>());
    EXPECT_EQ(p.figure("colour_chroma"), c["chroma"]["mean"].get<double>());
    EXPECT_EQ(p.figure("colour_windowed"), c["windowed"]["share"].get<double>());
    EXPECT_EQ(p.stderrOf("colour_windowed"), c["windowed"]["stderr"].get<double>());
    EXPECT_EQ(p.figure("colour_extinct"), c["extinct"]["share"].get<double>());
    EXPECT_EQ(p.figure("colour_saturated"), c["saturated"]["share"].get<double>());
    // The two depths differ: the figure follows the cut.
    EXPECT_NE(result.points[0].figure("colour_lightness"), p.figure("colour_lightness"));

    // A point kept by a build without colour figures is traced again, to the same bits.
    std::vector<nlohmann::json> kept;
    for (const SweepPoint& q : result.points) kept.push_back(sweepPointJson(plan, q));
    kept[0].erase("colour");
    SweepPointHooks hooks;
    hooks.restore = [&](size_t k) { return std::optional(kept[k]); };
    RunControl resumed;
    const SweepResult again = runSweep(plan, resumed, hooks);
    EXPECT_EQ(sweepToJson(again)["points"].dump(), sweepToJson(result)["points"].dump());
}

// Colour figures need the colour view; the colour view needs an absorbing point and axes it sees.
TEST(ColourSweep, RefusesWhatTheColourViewCannotMeasure) {
    const TraceSettings sapphire = [] {
        TraceSettings t = quickTrace();
        t.material = "blue_sapphire";
        return t;
    }();
    const auto plan = [&](const std::vector<std::string>& axes, const std::string& figure,
                          const TraceSettings& t, const std::optional<ColourSettings>& colour) {
        return fieldOf([&] { planSweep("round_brilliant", requestOf(axes, figure), t, colour); });
    };
    EXPECT_EQ(plan({"size_mm=3,6"}, "colour_lightness", sapphire, coarseColour()), "");
    EXPECT_EQ(plan({"size_mm=3,6"}, "colour_lightness", sapphire, std::nullopt), "sweep.figure");
    try {
        checkSweepFigure("colour_extinct", sapphire, false);
        ADD_FAILURE() << "a colour figure without the colour view";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("--colour"), std::string::npos) << e.what();
    }
    // Nothing absorbs: a clear material, or a constant n.
    EXPECT_EQ(plan({"size_mm=3,6"}, "colour_lightness", quickTrace(), coarseColour()), "material");
    EXPECT_EQ(plan({"n=1.5,1.7"}, "colour_lightness", quickTrace(), coarseColour()), "material");
    // One absorbing material of the axis is enough; so is a job's own spectrum on a clear material.
    EXPECT_EQ(plan({"material=quartz,amethyst"}, "colour_lightness", quickTrace(), coarseColour()), "");
    TraceSettings tinted = quickTrace();
    tinted.material = "quartz";
    tinted.absorption = AbsorptionSpectrum{{400, 700}, {0.1, 0.5}, {}};
    EXPECT_EQ(plan({"size_mm=3,6"}, "colour_lightness", tinted, coarseColour()), "");
    // A job's spectrum of zeros replaces a coloured material's: the spectrum is at fault, not the material.
    for (const char* absorption :
         {R"({"wavelength_nm": [400, 700], "ordinary_per_mm": [0, 0]})", R"({"corundum_ppma": {"cr": 0}})"}) {
        TraceSettings zero = quickTrace();
        zero.material = "ruby";
        zero.absorption = readAbsorption(nlohmann::json::parse(absorption), "absorption");
        EXPECT_EQ(plan({"size_mm=3,6"}, "colour_lightness", zero, coarseColour()), "absorption")
            << absorption;
        EXPECT_EQ(plan({"material=ruby,blue_sapphire"}, "colour_lightness", zero, coarseColour()),
                  "absorption")
            << absorption;
    }
    // The view is face-up under a dome of its own: the light's axes change nothing it sees.
    EXPECT_EQ(plan({"size_mm=3,6", "tilt=0,10"}, "colour_lightness", sapphire, coarseColour()),
              "sweep.axes[1]");
    EXPECT_EQ(plan({"head_shadow=0,10"}, "brightness", sapphire, coarseColour()), "sweep.axes[0]");
    EXPECT_EQ(plan({"light=hemisphere,point"}, "weighted_return", sapphire, coarseColour()), "sweep.axes[0]");
    // The size axis is checked as the size setting is.
    EXPECT_EQ(plan({"size_mm=0.01,6"}, "colour_lightness", sapphire, coarseColour()), "sweep.axes[0]");
}

namespace {

// The colour through the table against the optic axis, traced at 8 mm from tilt 0 (c along the table's
// normal) to tilt 90 (c lying in the table): the change of L*, a*, b* between them and its error.
struct AxisTurn {
    Lab change, sigma;
};
AxisTurn turnTheAxis(TraceSettings trace) {
    ColourSettings colour = coarseColour();
    colour.pictureSize = 120;
    trace.sizeMm = 8;
    RunControl control;
    const SweepResult r = runSweep(
        planSweep("round_brilliant", requestOf({"optic_axis_tilt=0,90"}, "colour_lightness"), trace, colour),
        control);
    EXPECT_EQ(r.points.size(), 2u);
    for (const SweepPoint& p : r.points) EXPECT_TRUE(p.ok()) << p.error;
    if (r.points.size() != 2) return {};
    const SweepPoint &along = r.points[0], &across = r.points[1];
    const auto change = [&](const char* f) { return across.figure(f) - along.figure(f); };
    const auto sigma = [&](const char* f) { return std::hypot(along.stderrOf(f), across.stderrOf(f)); };
    return {{change("colour_lightness"), change("colour_a"), change("colour_b")},
            {sigma("colour_lightness"), sigma("colour_a"), sigma("colour_b")}};
}

// What the spectra alone predict (the CIE sums of tests/optics/gem_spectra_test.cpp, D65, no surface):
// through `mm` along c both waves absorb by alpha_o; across c unpolarised light halves into an o and an e
// wave.
Lab predictedTurn(const AbsorptionSpectrum& s, double mm) {
    const auto lab = [&](const std::function<double(double)>& tau) {
        return xyzToLab(tristimulus(Illuminant::D65, tau), whitePoint(Illuminant::D65));
    };
    const Lab along = lab([&](double nm) { return std::exp(-s.ordinary(nm) * mm); });
    const Lab across = lab([&](double nm) {
        return (std::exp(-s.ordinary(nm) * mm) + std::exp(-s.extraordinary(nm) * mm)) / 2;
    });
    return {across.L - along.L, across.a - along.a, across.b - along.b};
}

}  // namespace

// Blue sapphire's o and e spectra differ (docs/optics.md, "Coloured materials"): turning its optic axis from
// the table's normal into the table moves the face-up colour by many errors, in L*, a* and b* each the way
// its spectra predict over the face-up view's paths (4 to 16 mm through an 8 mm stone).
TEST(ColourSweep, TheOpticAxisTurnsAPleochroicStonesColour) {
    const AbsorptionSpectrum spectrum = *gemSpectrum("blue_sapphire");
    const Lab shortPath = predictedTurn(spectrum, 4), longPath = predictedTurn(spectrum, 16);
    TraceSettings trace = quickTrace();
    trace.material = "blue_sapphire";
    const AxisTurn turn = turnTheAxis(trace);
    const std::array<std::tuple<const char*, double, double, double, double>, 3> figures{
        {{"L*", shortPath.L, longPath.L, turn.change.L, turn.sigma.L},
         {"a*", shortPath.a, longPath.a, turn.change.a, turn.sigma.a},
         {"b*", shortPath.b, longPath.b, turn.change.b, turn.sigma.b}}};
    for (const auto& [name, predictedShort, predictedLong, change, sigma] : figures) {
        SCOPED_TRACE(name);
        // The spectra agree with themselves over the path lengths, by more than a unit of Lab.
        ASSERT_GT(predictedShort * predictedLong, 0);
        ASSERT_GT(std::min(std::abs(predictedShort), std::abs(predictedLong)), 1);
        EXPECT_GT(predictedShort > 0 ? change : -change, 5 * sigma)
            << "traced " << change << " +- " << sigma << ", the spectra say " << predictedShort << " to "
            << predictedLong;
    }
}

// A uniaxial stone whose table has no e column absorbs both waves alike (e as o): the same sapphire with its
// E perp c column alone shows one colour whichever way its axis lies, within the errors. What is left is the
// doubly refracting stone's geometry (the e wave's own path), not colour.
TEST(ColourSweep, AStoneWithoutAnEColumnKeepsItsColourAcrossTheAxis) {
    AbsorptionSpectrum ordinaryOnly = *gemSpectrum("blue_sapphire");
    ordinaryOnly.extraordinaryPerMm.clear();
    TraceSettings trace = quickTrace();
    trace.material = "blue_sapphire";
    trace.absorption = ordinaryOnly;
    const AxisTurn turn = turnTheAxis(trace);
    EXPECT_LT(std::abs(turn.change.L), 3 * turn.sigma.L) << turn.change.L << " +- " << turn.sigma.L;
    EXPECT_LT(std::abs(turn.change.a), 3 * turn.sigma.a) << turn.change.a << " +- " << turn.sigma.a;
    EXPECT_LT(std::abs(turn.change.b), 3 * turn.sigma.b) << turn.change.b << " +- " << turn.sigma.b;
}

TEST(ColourSweep, TheOpticAxisIsSweptOnlyWhereItMeansSomething) {
    const SweepRequest request = requestOf({"optic_axis_tilt=0:90:45"}, "crown_return");
    TraceSettings trace = quickTrace();
    trace.material = "diamond";
    EXPECT_NE(fieldOf([&] { planSweep("round_brilliant", request, trace, std::nullopt); }).find("sweep.axes"),
              std::string::npos);
    try {
        planSweep("round_brilliant", request, trace, std::nullopt);
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("needs a doubly refracting"), std::string::npos) << e.what();
    }
    trace.material = "sapphire";
    EXPECT_EQ(fieldOf([&] { planSweep("round_brilliant", request, trace, std::nullopt); }), "");
    // A biaxial stone's Z axis tilts as a uniaxial one's axis does; its X turns about Z only for a biaxial
    // one.
    const SweepRequest rotation = requestOf({"optic_axis_rotation=0,90"}, "crown_return");
    try {
        planSweep("round_brilliant", rotation, trace, std::nullopt);
        ADD_FAILURE() << "a uniaxial stone has no X axis to turn";
    } catch (const Error& e) {
        EXPECT_NE(e.field().find("sweep.axes"), std::string::npos) << e.field();
        EXPECT_NE(std::string(e.what()).find("needs a biaxial material"), std::string::npos) << e.what();
    }
    trace.material = "topaz";
    EXPECT_EQ(fieldOf([&] { planSweep("round_brilliant", request, trace, std::nullopt); }), "");
    EXPECT_EQ(fieldOf([&] { planSweep("round_brilliant", rotation, trace, std::nullopt); }), "");
    trace.material = "sapphire";
    trace.polarization = PolarizationMode::Off;
    EXPECT_NE(fieldOf([&] { planSweep("round_brilliant", request, trace, std::nullopt); }).find("sweep.axes"),
              std::string::npos);
    trace.polarization = PolarizationMode::On;
    EXPECT_NE(fieldOf([&] {
                  planSweep("round_brilliant",
                            requestOf({"optic_axis_tilt=0,90", "material=sapphire,quartz"}, "crown_return"),
                            trace, std::nullopt);
              }).find("sweep.axes"),
              std::string::npos);
    EXPECT_NE(fieldOf([&] {
                  planSweep("round_brilliant", requestOf({"optic_axis_tilt=0,200"}, "crown_return"), trace,
                            std::nullopt);
              }).find("sweep.axes"),
              std::string::npos)
        << "beyond the setting's own range";
    // An axis along the table's normal has no azimuth to turn: an azimuth axis needs it tilted, or a tilt
    // axis.
    const auto azimuthField = [&](const std::vector<std::string>& axes) {
        return fieldOf(
            [&] { planSweep("round_brilliant", requestOf(axes, "crown_return"), trace, std::nullopt); });
    };
    EXPECT_EQ(azimuthField({"optic_axis_azimuth=0,45"}), "sweep.axes[0]");
    EXPECT_EQ(azimuthField({"optic_axis_tilt=0,45", "optic_axis_azimuth=0,45"}), "");
    trace.opticAxis.tiltDeg = 180;
    EXPECT_EQ(azimuthField({"pavilion=40,41", "optic_axis_azimuth=0,45"}), "sweep.axes[1]");
    trace.opticAxis.tiltDeg = 30;
    EXPECT_EQ(azimuthField({"optic_axis_azimuth=0,45"}), "");
    // A biaxial stone's Z turned over: there the azimuth turns its X (180 + 2 azimuth - rotation deg).
    trace.material = "topaz";
    trace.opticAxis.tiltDeg = 180;
    EXPECT_EQ(azimuthField({"optic_axis_azimuth=0,45"}), "");
    trace.opticAxis.tiltDeg = 0;
    EXPECT_EQ(azimuthField({"optic_axis_azimuth=0,45"}), "sweep.axes[0]");
    trace.material = "sapphire";
    trace.opticAxis.tiltDeg = 30;
    // An n axis leaves no optic axis to turn; a job's own material is not swept away by a material or n axis.
    EXPECT_NE(fieldOf([&] {
                  planSweep("round_brilliant",
                            requestOf({"optic_axis_tilt=0,90", "n=1.7,1.8"}, "crown_return"), trace,
                            std::nullopt);
              }).find("sweep.axes"),
              std::string::npos);
    TraceSettings own = quickTrace();
    own.customMaterial = readMaterialDefinition({{"n_o", 1.644}, {"n_e", 1.624}}, "custom_material");
    for (const char* axis : {"material=sapphire,quartz", "n=1.7,1.8"})
        EXPECT_NE(fieldOf([&] {
                      planSweep("round_brilliant", requestOf({axis}, "crown_return"), own, std::nullopt);
                  }).find("sweep.axes"),
                  std::string::npos)
            << axis;
    EXPECT_EQ(fieldOf([&] {
                  planSweep("round_brilliant", requestOf({"optic_axis_tilt=0,90"}, "crown_return"), own,
                            std::nullopt);
              }),
              "")
        << "a job's own uniaxial material has an optic axis to turn";
}
