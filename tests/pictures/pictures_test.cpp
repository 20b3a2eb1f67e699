// The pictures' words and colour scales: what a person reads off them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "optics/absorption.h"
#include "pictures/colormap.h"
#include "pictures/colour_picture.h"
#include "pictures/doubling_picture.h"
#include "pictures/heatmap.h"
#include "pictures/share_chart.h"
#include "pictures/tilt_chart.h"
#include "support/fixtures.h"
#include "support/picture_checks.h"

namespace facetlight {
namespace {

using test::colourDistance;
using test::fillOf;
using test::inkShare;

TiltSeries switchedOf(uint64_t switched, uint64_t pixelPairs) {
    TiltSeries series;
    series.switched = switched;
    series.pixelPairs = pixelPairs;
    return series;
}

// The pictures name the material traced, not the job's "auto": the default's diamond, or a job's own.
TEST(PictureTitles, NameTheMaterialTraced) {
    TraceSettings settings;
    EXPECT_NE(colourTitle(test::roundBrilliant(), settings).find(", diamond, 6.5 mm"), std::string::npos);
    settings.customMaterial = MaterialDefinition{};
    settings.customMaterial->name = "my spinel";
    settings.customMaterial->n = 1.718;
    EXPECT_NE(colourTitle(test::roundBrilliant(), settings).find(", my spinel, "), std::string::npos);
    EXPECT_NE(doublingTitle(test::roundBrilliant(), settings).find(", my spinel, "), std::string::npos);
}

// A job's own spectrum replaces the material's colour, so the colour picture's title says by what.
TEST(PictureTitles, NameWhatAJobsOwnSpectrumColoursTheStoneBy) {
    TraceSettings settings;
    settings.material = "ruby";
    EXPECT_NE(colourTitle(test::roundBrilliant(), settings).find(", ruby, 6.5 mm"), std::string::npos);
    settings.absorption = readAbsorption({{"corundum_ppma", {{"cr", 1000}, {"fe_ti", 20}}}}, "absorption");
    EXPECT_NE(colourTitle(test::roundBrilliant(), settings)
                  .find(", ruby coloured by Cr3+ 1000 ppma, Fe2+-Ti4+ 20 ppma, 6.5 mm"),
              std::string::npos);
    settings.absorption = readAbsorption({{"corundum_ppma", {{"fe_ti", 2.5}}}}, "absorption");
    EXPECT_NE(colourTitle(test::roundBrilliant(), settings).find(" coloured by Fe2+-Ti4+ 2.5 ppma, "),
              std::string::npos);
    settings.absorption =
        readAbsorption({{"wavelength_nm", {400, 700}}, {"ordinary_per_mm", {0.1, 0.2}}}, "absorption");
    EXPECT_NE(
        colourTitle(test::roundBrilliant(), settings).find(" coloured by the job's absorption spectrum, "),
        std::string::npos);
}

// The scintillation is written to its standard error's digits: a small error is not rounded to "0.0", a
// larger one keeps its second digit when it starts with 1, and a share with no error is written alone.
TEST(TiltChart, SubtitleWritesTheErrorToItsDigits) {
    // 7.4 % of a million pixel pairs: +- 0.026 %.
    EXPECT_EQ(tiltChartSubtitle(switchedOf(74'000, 1'000'000)),
              "ASET view, lit = bright or low light; scintillation 7.40 +- 0.03 % per frame");
    // 20 % of 10 000: +- 0.4 %.
    EXPECT_EQ(tiltChartSubtitle(switchedOf(2'000, 10'000)),
              "ASET view, lit = bright or low light; scintillation 20.0 +- 0.4 % per frame");
    // 50 % of 2 000 000: +- 0.035 %; 0.05 % of 2 000 000: +- 0.0016 %, two digits as it starts with 1.
    EXPECT_NE(tiltChartSubtitle(switchedOf(1'000'000, 2'000'000)).find(" 50.00 +- 0.04 %"),
              std::string::npos);
    EXPECT_NE(tiltChartSubtitle(switchedOf(1'000, 2'000'000)).find(" 0.0500 +- 0.0016 %"), std::string::npos);
    // No pixel switched: a share, no error.
    EXPECT_EQ(tiltChartSubtitle(switchedOf(0, 1000)),
              "ASET view, lit = bright or low light; scintillation 0.0 % per frame");
    for (const uint64_t n : {10ull, 1'000ull, 100'000ull, 10'000'000ull}) {
        EXPECT_EQ(tiltChartSubtitle(switchedOf(n / 3, n)).find("+- 0.0 "), std::string::npos) << n;
        EXPECT_EQ(tiltChartSubtitle(switchedOf(n / 3, n)).find("+- 0 "), std::string::npos) << n;
    }
}

// A design whose table takes 47.5 % of the light and whose other facets 0.2 to 1 % each: the colour scale
// ends at 1 %, so that every other facet is filled by its own share on it (on a scale to the table's 47.5 %,
// all of them would be the same dark purple); the table, beyond the scale, is filled in the top colour and
// hatched. The fire view draws the same way.
// A long stone name keeps the chart's title inside the picture (at 1.5 it ran off both edges).
TEST(ShareChart, ALongTitleStaysInside) {
    const Image chart = shareChart(
        {{0, 0.1, 0.01}, {45, 0.5, 0.01}, {90, 0.1, 0.01}},
        {"Polariscope: a stone with a name much too long for one line at the "
         "title's size, round brilliant, sapphire",
         "dark at 0, 90, 180 and 270 deg of a turn: doubly refracting", "stone turned (deg)", "share (%)"});
    int inkAtTheEdges = 0;
    for (int y = 0; y < 40; ++y)
        for (int x : {0, 1, 2, 3, chart.width() - 4, chart.width() - 3, chart.width() - 2, chart.width() - 1})
            inkAtTheEdges += colourDistance(chart.at(x, y), {1, 1, 1}) > 0.01;
    EXPECT_EQ(inkAtTheEdges, 0);
}

TEST(Heatmap, ScaleShowsTheFacetsOtherThanTheTable) {
    const Stone& stone = test::roundBrilliant();
    const HeatmapLayout layout = heatmapLayout(stone);
    FacetStats stats(stone.facets.size());
    stats.photons = stats.hit = 100'000;
    FireStats fire(stone.facets.size());
    fire.coloured = 100'000;
    std::vector<double> share(stone.facets.size(), 0);
    int k = 0;
    for (const HeatmapFacet& f : layout.facets) {
        share[f.facet] = stone.facets[f.facet].region == Region::Table ? 0.475 : 0.002 * (1 + k++ % 5);
        stats.facets[f.facet].leaving = fire.colouredByFacet[f.facet] =
            uint64_t(std::llround(share[f.facet] * 100'000));
    }
    for (const Image& heatmap : {facetHeatmap(stone, stats), fireHeatmap(stone, fire)}) {
        ASSERT_EQ(heatmap.width(), layout.width);
        ASSERT_EQ(heatmap.height(), layout.height);
        for (const HeatmapFacet& f : layout.facets) {
            const std::string& name = stone.facets[f.facet].name;
            if (stone.facets[f.facet].region == Region::Table) {
                EXPECT_LT(colourDistance(fillOf(heatmap, f.outline), viridis(1)), 0.02) << name;
                EXPECT_GT(inkShare(heatmap, f.outline), 0.15) << name << ": not hatched";
            } else {
                EXPECT_LT(colourDistance(fillOf(heatmap, f.outline), viridis(share[f.facet] / 0.01)), 0.03)
                    << name;
            }
        }
    }
}

// Every facet that holds a label at a legible size carries one: some pixels around its centroid differ from
// its fill. A round brilliant of this size labels most of its facets.
TEST(Heatmap, LabelsEveryFacetThatHoldsOne) {
    const Stone& stone = test::roundBrilliant();
    const HeatmapLayout layout = heatmapLayout(stone);
    FacetStats stats(stone.facets.size());
    stats.photons = stats.hit = 100'000;
    int k = 0;
    for (const HeatmapFacet& f : layout.facets) stats.facets[f.facet].leaving = 300 + 200 * (k++ % 7);
    const Image heatmap = facetHeatmap(stone, stats);
    const std::array<Point2, 4> corners = {Point2{-1, -1}, Point2{1, -1}, Point2{1, 1}, Point2{-1, 1}};
    int labelled = 0, roomy = 0;
    for (const HeatmapFacet& f : layout.facets) {
        const Rgb fill = fillOf(heatmap, f.outline);
        int marked = 0;
        for (int dy = -6; dy <= 6; ++dy)
            for (int dx = -12; dx <= 12; ++dx)
                marked +=
                    colourDistance(heatmap.at(int(f.centroid[0]) + dx, int(f.centroid[1]) + dy), fill) > 0.3;
        // A box of 44 x 26 pixels about the centroid holds "1.5" 14 pixels high.
        const bool holds = std::all_of(corners.begin(), corners.end(), [&](const Point2& c) {
            return test::inside(f.outline, {f.centroid[0] + 22 * c[0], f.centroid[1] + 13 * c[1]});
        });
        roomy += holds;
        if (holds) {
            EXPECT_GT(marked, 20) << stone.facets[f.facet].name << " holds a label but has none";
        }
        labelled += marked > 20;
    }
    EXPECT_GE(roomy, 20);
    EXPECT_GE(labelled, roomy);
}

}  // namespace
}  // namespace facetlight
