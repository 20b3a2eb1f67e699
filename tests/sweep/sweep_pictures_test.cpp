#include "sweep/sweep_pictures.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "sweep/sweep_references.h"
#include "util/error.h"

using namespace facetlight;

namespace {

SweepResult smallSweep(std::vector<std::string> axes) {
    SweepPlan plan;
    plan.shape = "round_brilliant";
    for (const std::string& a : axes) plan.axes.push_back(parseSweepAxis(a));
    plan.trace.photons = 3000;
    plan.trace.threads = 2;
    RunControl control;
    return runSweep(plan, control);
}

bool dark(const Rgb& c) {
    return c.r < 0.45f && c.g < 0.45f && c.b < 0.45f;
}

// What a picture with a plot in it has and a blank or frameless one lacks: many colours, and long dark lines
// (the frame) across at least `lines` rows and columns, with text (tick labels) under the lowest.
void expectPlotWithAxes(const Image& image, size_t minColours) {
    std::set<std::tuple<int, int, int>> colours;
    std::vector<int> darkInRow(image.height()), darkInColumn(image.width());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const Rgb& c = image.at(x, y);
            colours.insert({int(c.r * 255), int(c.g * 255), int(c.b * 255)});
            if (dark(c)) ++darkInRow[y], ++darkInColumn[x];
        }
    EXPECT_GE(colours.size(), minColours);
    std::vector<int> frameRows, frameColumns;
    for (int y = 0; y < image.height(); ++y)
        if (darkInRow[y] > image.width() / 2) frameRows.push_back(y);
    for (int x = 0; x < image.width(); ++x)
        if (darkInColumn[x] > image.height() / 2) frameColumns.push_back(x);
    ASSERT_GE(frameRows.size(), 2u);  // top and bottom of the frame
    EXPECT_GE(frameColumns.size(), 2u);
    int labelInk = 0;  // tick labels and the axis label under the frame
    for (int y = frameRows.back() + 8; y < std::min(image.height(), frameRows.back() + 50); ++y)
        labelInk += darkInRow[y];
    EXPECT_GT(labelInk, 200);
}

}  // namespace

TEST(SweepPictures, MapIsFilledAndCarriesAxesAndScale) {
    const SweepResult result = smallSweep({"pavilion=39:42:1", "crown=32:36:2"});
    const auto pictures = sweepPictures(result, {"weighted_return"});
    ASSERT_EQ(pictures.size(), 1u);
    EXPECT_EQ(pictures[0].first, "map_weighted_return.png");
    const Image& map = pictures[0].second;
    expectPlotWithAxes(map, 12);
    // The contour bands fill the frame: most of its middle row is neither white nor grey.
    int coloured = 0;
    const int y = map.height() / 2;
    for (int x = 0; x < map.width(); ++x) {
        const Rgb& c = map.at(x, y);
        coloured += std::max({c.r, c.g, c.b}) - std::min({c.r, c.g, c.b}) > 0.2f;
    }
    EXPECT_GT(coloured, map.width() / 2);
    EXPECT_EQ(*highestPoint(result, "weighted_return") < result.points.size(), true);
}

TEST(SweepPictures, CurvesCarryEachFigureAndAxes) {
    const SweepResult result = smallSweep({"pavilion=38:43:0.5"});
    const auto pictures = sweepPictures(result, {"weighted_return", "leakage"});
    ASSERT_EQ(pictures.size(), 1u);
    EXPECT_EQ(pictures[0].first, "curves.png");
    expectPlotWithAxes(pictures[0].second, 8);
    EXPECT_THROW(sweepPictures(result, {"sparkle"}), Error);
    EXPECT_THROW(sweepPictures(result, {"coloured_share"}), Error);  // no fire traced
}

// A fire figure is drawn like any other: a map, and curves with their bands beside a share.
// Issue 30: curves.png names the parameters held and the highest point.
TEST(SweepPictures, CurvesTitleNamesTheHeldParametersAndTheHighestPoint) {
    SweepPlan plan;
    plan.shape = "round_brilliant";
    plan.axes.push_back(parseSweepAxis("pavilion=40,42"));
    plan.fixed = {{"crown", 34.5}};
    plan.trace.photons = 2000;
    plan.trace.threads = 2;
    plan.trace.viewer.enabled = false;
    RunControl control;
    const SweepResult result = runSweep(plan, control);
    const std::string title = sweepCurvesTitle(result, {"weighted_return"});
    EXPECT_EQ(title.rfind("round_brilliant with crown 34.5; ", 0), 0u) << title;
    const size_t best = *highestPoint(result, "weighted_return");
    EXPECT_NE(title.find("; highest weighted return 0."), std::string::npos) << title;
    EXPECT_NE(title.find(" at pavilion " + std::string(best == 0 ? "40" : "42")), std::string::npos) << title;
}

TEST(SweepPictures, FireFiguresAreDrawnWhenFireIsTraced) {
    const auto fireSweep = [](std::vector<std::string> axes) {
        SweepPlan plan;
        plan.shape = "round_brilliant";
        for (const std::string& a : axes) plan.axes.push_back(parseSweepAxis(a));
        plan.trace.photons = 2000;
        plan.trace.threads = 2;
        plan.trace.fire.enabled = true;
        RunControl control;
        return runSweep(plan, control);
    };
    const auto maps =
        sweepPictures(fireSweep({"pavilion=39,41", "crown=32,35"}), {"coloured_return_weighted"});
    ASSERT_EQ(maps.size(), 1u);
    EXPECT_EQ(maps[0].first, "map_coloured_return_weighted.png");
    expectPlotWithAxes(maps[0].second, 8);
    expectPlotWithAxes(
        sweepCurves(fireSweep({"pavilion=39:42:1"}), {"weighted_return", "mean_separation_deg"}), 8);
}

// The reference designs the map rings (and the service's points answer lists) lie at their parameters'
// values on the axes, in the axes' order; none where an axis is not a parameter of theirs.
TEST(SweepPictures, ReferenceDesignsLieAtTheirValuesOnTheAxes) {
    SweepPlan plan;
    plan.shape = "round_brilliant";
    plan.axes = {parseSweepAxis("pavilion=39:42:1"), parseSweepAxis("crown=32:36:2")};
    const std::vector<SweepReference> refs = sweepReferences(plan);
    ASSERT_EQ(refs.size(), 2u);
    EXPECT_EQ(refs[0].label, "GIA reference");
    EXPECT_EQ(refs[0].values, (std::vector<double>{40.7, 34}));
    EXPECT_EQ(refs[1].label, "Tolkowsky 1919");
    EXPECT_EQ(refs[1].values, (std::vector<double>{40.75, 34.5}));
    std::swap(plan.axes[0], plan.axes[1]);
    EXPECT_EQ(sweepReferences(plan)[0].values, (std::vector<double>{34, 40.7}));
    plan.axes[1] = parseSweepAxis("tilt=0,10");
    EXPECT_TRUE(sweepReferences(plan).empty());
    plan.axes[1] = parseSweepAxis("material=diamond,cubic_zirconia");
    EXPECT_TRUE(sweepReferences(plan).empty());
}
