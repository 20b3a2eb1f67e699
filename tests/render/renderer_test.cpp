// The renderer and its pictures: determinism across thread counts, image sizes and content, PNG output,
// colour science, photon-map irradiance against the analytic value, and render settings validation.
#include "render/renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "cuts/mesh_resolver.h"
#include "image/image.h"
#include "optics/spectrum.h"
#include "photonmap/floor_photons.h"
#include "photonmap/photon_map.h"
#include "pictures/angular_plot.h"
#include "pictures/colormap.h"
#include "pictures/heatmap.h"
#include "scene/scene.h"
#include "study/study.h"
#include "support/fixtures.h"
#include "support/picture_checks.h"
#include "trace/photon_tracer.h"
#include "util/error.h"

namespace facetlight {
namespace {

using test::changedPixels;
using test::colourDistance;
using test::fillOf;
using test::roundBrilliant;

TraceSettings smallTrace(int threads) {
    TraceSettings t;
    t.photons = 20'000;
    t.threads = threads;
    t.seed = 7;
    return t;
}

RenderSettings smallRender() {
    RenderSettings r;
    r.width = 64;
    r.height = 48;
    r.samples = 3;
    r.mapPhotons = 20'000;
    return r;
}

RenderedImage renderWith(int threads, const RenderSettings& r) {
    const TraceSettings t = smallTrace(threads);
    const Scene scene(roundBrilliant(), t);
    const TraceBase trace(scene, t);
    FloorPhotons photons = traceFloorPhotons(trace, r.mapPhotons, threads);
    const PhotonMap caustics(std::move(photons.caustic), threads);
    return render(scene, caustics, r, threads, t.seed);
}

double lumaVariance(const RenderedImage& image) {
    double sum = 0, sum2 = 0;
    for (const Vec3& p : image.pixels) {
        const double l = p.x + p.y + p.z;
        sum += l;
        sum2 += l * l;
    }
    const double n = double(image.pixels.size());
    return sum2 / n - (sum / n) * (sum / n);
}

// Width and height from a PNG's IHDR chunk, after checking the signature.
std::pair<uint32_t, uint32_t> pngSize(const std::string& png) {
    EXPECT_GE(png.size(), 24u);
    EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
    EXPECT_EQ(png.substr(12, 4), "IHDR");
    auto be32 = [&](size_t at) {
        return uint32_t(uint8_t(png[at])) << 24 | uint32_t(uint8_t(png[at + 1])) << 16 |
               uint32_t(uint8_t(png[at + 2])) << 8 | uint32_t(uint8_t(png[at + 3]));
    };
    return {be32(16), be32(20)};
}

TEST(Renderer, SameBitsForOneAndTwoThreads) {
    const RenderSettings r = smallRender();
    const RenderedImage one = renderWith(1, r), two = renderWith(2, r);
    ASSERT_EQ(one.pixels.size(), size_t(r.width * r.height));
    ASSERT_EQ(two.pixels.size(), one.pixels.size());
    for (size_t i = 0; i < one.pixels.size(); ++i) {
        ASSERT_EQ(one.pixels[i], two.pixels[i]) << "pixel " << i;
    }
    EXPECT_GT(lumaVariance(one), 1e-4);
}

TEST(Renderer, FloorPhotonsDoNotDependOnThreads) {
    const TraceSettings t = smallTrace(1);
    const Scene scene(roundBrilliant(), t);
    const TraceBase trace(scene, t);
    const FloorPhotons a = traceFloorPhotons(trace, 30'000, 1);
    const FloorPhotons b = traceFloorPhotons(trace, 30'000, 2);
    ASSERT_EQ(a.caustic.size(), b.caustic.size());
    EXPECT_GT(a.caustic.size(), 0u);
    EXPECT_EQ(0, std::memcmp(a.caustic.data(), b.caustic.data(), a.caustic.size() * sizeof(Photon)));
    EXPECT_EQ(a.crownExits.counts, b.crownExits.counts);
    EXPECT_GT(a.crownExits.total, 0u);
}

TEST(Renderer, CancelledBeforeStartRendersNothing) {
    const TraceSettings t = smallTrace(2);
    const Scene scene(roundBrilliant(), t);
    RunControl control;
    control.cancel();
    const RenderedImage image = render(scene, PhotonMap(), smallRender(), 2, 1, &control);
    EXPECT_TRUE(image.cancelled);
    EXPECT_EQ(control.done(), 0u);
}

TEST(Renderer, ProgressCountsEveryPixel) {
    const TraceSettings t = smallTrace(2);
    const Scene scene(roundBrilliant(), t);
    RunControl control;
    RenderSettings r = smallRender();
    r.width = 37;  // tiles that do not divide the image
    const RenderedImage image = render(scene, PhotonMap(), r, 2, 1, &control);
    EXPECT_FALSE(image.cancelled);
    EXPECT_EQ(control.done(), uint64_t(37 * 48));
}

TEST(Study, WritesThreePicturesOfTheStatedSizes) {
    StudySettings s;
    s.trace = smallTrace(2);
    s.render = smallRender();
    RunControl control;
    const StudyResult result = runStudy(roundBrilliant(), s, control);
    EXPECT_EQ(pngSize(result.file("render.png")), std::make_pair(64u, 48u));
    EXPECT_GT(pngSize(result.file("heatmap.png")).first, 0u);
    EXPECT_GT(pngSize(result.file("angular.png")).first, 0u);
    EXPECT_EQ(result.stats["totals"]["photons"], 20'000);
    EXPECT_NE(result.file("stats.csv").find(",leaving_share,leaving_share_stderr\n"), std::string::npos);
    EXPECT_EQ(control.phase(), RunPhase::Done);
}

TEST(Study, StatisticsOnlyWithoutRender) {
    StudySettings s;
    s.trace = smallTrace(1);
    RunControl control;
    const StudyResult result = runStudy(roundBrilliant(), s, control);
    EXPECT_TRUE(result.file("render.png").empty());
    EXPECT_TRUE(result.file("angular.png").empty());
    EXPECT_FALSE(result.file("heatmap.png").empty());
}

// stone.json, the page's 3-D view: the stone as traced, facet for facet as the statistics number them, each
// outline a polygon on its facet's plane, turned outward, in mm at the job's size_mm.
TEST(Study, StoneJsonIsTheStoneAsTracedInMm) {
    StudySettings s;
    s.trace = smallTrace(1);
    s.trace.viewer.enabled = false;
    s.trace.sizeMm = 8;
    RunControl control;
    const Stone& stone = roundBrilliant();
    const StudyResult result = runStudy(stone, s, control);
    const nlohmann::json geometry = nlohmann::json::parse(result.file("stone.json"));
    EXPECT_EQ(geometry["units"], "mm");
    const double mm = 8 / stone.proportions.diameter;
    EXPECT_DOUBLE_EQ(geometry["mm_per_unit"].get<double>(), mm);
    const nlohmann::json& facets = geometry["facets"];
    const nlohmann::json& stats = result.stats["facets"];
    ASSERT_EQ(facets.size(), stats.size());
    ASSERT_EQ(facets.size(), stone.facets.size());
    double radius = 0;
    for (size_t i = 0; i < facets.size(); ++i) {
        const nlohmann::json& f = facets[i];
        SCOPED_TRACE(f.dump());
        EXPECT_EQ(f["id"], stats[i]["id"]);
        EXPECT_EQ(f["name"], stats[i]["name"]);
        EXPECT_EQ(f["region"], stats[i]["region"]);
        const Facet& facet = stone.facets.at(f["id"].get<size_t>());
        const nlohmann::json& corners = f["vertices"];
        ASSERT_GE(corners.size(), 3u);
        std::vector<Vec3> p;
        for (const nlohmann::json& c : corners) p.push_back({c[0], c[1], c[2]});
        Vec3 newell{};  // the polygon's own normal (Newell's method): which way round it goes
        for (size_t k = 0; k < p.size(); ++k) {
            const Vec3& a = p[k];
            const Vec3& b = p[(k + 1) % p.size()];
            newell += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
            // On the facet's plane scaled to mm, to the file's 10 nm.
            EXPECT_NEAR(dot(facet.normal, a), facet.offset * mm, 2e-5);
            radius = std::max(radius, std::hypot(a.x, a.y));
        }
        EXPECT_GT(dot(normalize(newell), facet.normal), 1 - 1e-6);
        EXPECT_NEAR(f["normal"][2].get<double>(), facet.normal.z, 1e-9);
    }
    // The girdle is size_mm across (a round's 16 girdle corners reach the circle the diameter is measured
    // on).
    EXPECT_NEAR(2 * radius, 8, 0.01);
}

TEST(Study, CancelThrowsCanceled) {
    StudySettings s;
    s.trace = smallTrace(1);
    s.render = smallRender();
    RunControl control;
    control.cancel();
    EXPECT_THROW(runStudy(roundBrilliant(), s, control), Canceled);
}

// The layout a page lays over the heat-map: every facet but the girdle's, once, inside the picture, far ones
// first, the table around the crown diagram's centre.
TEST(Pictures, HeatmapLayoutPlacesEveryDrawnFacet) {
    const Stone& stone = roundBrilliant();
    const HeatmapLayout layout = heatmapLayout(stone);
    EXPECT_EQ(layout.facets.size(), stone.facets.size() - stone.facetCount(Region::Girdle));
    std::vector<int> seen(stone.facets.size(), 0);
    double lastZ[2] = {-INFINITY, INFINITY};
    for (const HeatmapFacet& f : layout.facets) {
        const Facet& facet = stone.facets[f.facet];
        ++seen[f.facet];
        EXPECT_EQ(f.side, facet.region == Region::Pavilion ? 1 : 0) << facet.name;
        EXPECT_EQ(f.outline.size(), facet.outline.size());
        for (const Point2& p : f.outline) {
            EXPECT_TRUE(p[0] >= 0 && p[0] <= layout.width && p[1] >= 0 && p[1] <= layout.height)
                << facet.name;
        }
        // Crown facets from the girdle up, pavilion facets from the girdle down.
        if (f.side == 0) {
            EXPECT_GE(facet.centroid.z, lastZ[0]) << facet.name;
        } else {
            EXPECT_LE(facet.centroid.z, lastZ[1]) << facet.name;
        }
        lastZ[f.side] = facet.centroid.z;
    }
    for (size_t i = 0; i < stone.facets.size(); ++i)
        EXPECT_EQ(seen[i], stone.facets[i].region == Region::Girdle ? 0 : 1) << stone.facets[i].name;
    // The table is drawn last on its side and its centroid is the crown diagram's centre.
    const HeatmapFacet& table = layout.facets[stone.facets.size() - stone.facetCount(Region::Girdle) -
                                              stone.facetCount(Region::Pavilion) - 1];
    EXPECT_EQ(stone.facets[table.facet].region, Region::Table);
    EXPECT_NEAR(table.centroid[0], layout.width * 0.25 + 5, 1.0);
    const nlohmann::json doc = toJson(layout, stone);
    ASSERT_EQ(doc["facets"].size(), layout.facets.size());
    EXPECT_EQ(doc["facets"][0]["points"].size(), layout.facets[0].outline.size());
    EXPECT_EQ(doc["facets"].back()["side"], "pavilion");
}

// Each facet is filled with the colour of its share: all the light through the table (the top of the scale)
// and none elsewhere (the bottom), the commonest colour inside each facet (its label aside); the same for the
// fire view (each facet's share of the fire). A picture with axes, titles and colour bar but no filled facets
// fails.
TEST(Pictures, HeatmapFillsEachFacetWithItsShare) {
    const Stone& stone = roundBrilliant();
    FacetStats stats(stone.facets.size());
    stats.photons = stats.hit = 1000;
    const HeatmapLayout layout = heatmapLayout(stone);
    const HeatmapFacet* table = nullptr;
    for (const HeatmapFacet& f : layout.facets) {
        if (stone.facets[f.facet].region == Region::Table) table = &f;
    }
    ASSERT_NE(table, nullptr);
    stats.facets[table->facet].leaving = 600;
    FireStats fire(stone.facets.size());  // the fire view: all the fire through the table too
    fire.coloured = fire.colouredByFacet[table->facet] = 40;
    for (const Image& heatmap : {facetHeatmap(stone, stats), fireHeatmap(stone, fire)}) {
        EXPECT_LT(colourDistance(fillOf(heatmap, table->outline), viridis(1)), 0.02);
        for (const HeatmapFacet& f : layout.facets) {
            if (&f == table) continue;
            EXPECT_LT(colourDistance(fillOf(heatmap, f.outline), viridis(0)), 0.02) << f.facet;
        }
    }
    // A traced stone's shares colour most of the diagrams, compared with a stone no light left.
    const TraceResult traced = test::traceStone(stone, smallTrace(2));
    const Image dark = facetHeatmap(stone, FacetStats(stone.facets.size()));
    EXPECT_GT(changedPixels(facetHeatmap(stone, traced.stats), dark).size(),
              size_t(dark.width()) * size_t(dark.height()) / 10);
}

// One direction lights one bin of the polar plot at the top of the colour scale and nothing else: the
// changed pixels against an empty histogram's plot are a small patch of that colour, above the disc's
// centre for an azimuth of about 100 degrees and below it for one of about 280.
TEST(Pictures, AngularPlotLightsTheBinOfEachDirection) {
    const Image empty = angularPlot(AngularHistogram(), "test");
    std::array<double, 2> patchY{};
    for (int k = 0; k < 2; ++k) {
        const double theta = radians(40.5), phi = radians(k == 0 ? 102.5 : 282.5);
        AngularHistogram h;
        for (int i = 0; i < 3; ++i)
            h.add({std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)});
        h.add({0, 0, -1});  // below the horizon: counted, not drawn
        EXPECT_EQ(h.total, 4u);
        const Image plot = angularPlot(h, "test");
        const auto changed = changedPixels(plot, empty);
        // The bin spans 1 degree by 5 degrees: about 3 by 11 pixels at this radius.
        ASSERT_GT(changed.size(), 15u) << k;
        EXPECT_LT(changed.size(), 100u) << k;
        // Pixels on the bin's rim and under the grid are blends; most are the top of the scale.
        double y = 0;
        size_t top = 0;
        for (const auto& p : changed) {
            top += colourDistance(plot.at(p[0], p[1]), viridis(1)) < 0.05;
            y += p[1];
        }
        EXPECT_GT(2 * top, changed.size()) << k;
        patchY[size_t(k)] = y / double(changed.size());
    }
    EXPECT_LT(patchY[0] + 200, patchY[1]);
}

// A subtitle too wide for one line is broken in two at the legible size (scale 2: glyphs 14 pixels high, from
// y 46 down to 60), not shrunk to scale 1.5 (down to 56.5, 8 pixels high on a 1400-pixel page).
TEST(Pictures, AngularPlotBreaksALongSubtitleAtTheLegibleSize) {
    const Image plot = angularPlot(
        AngularHistogram(), "3735 of 5000 photons (collimated light), refracted out of table and crown");
    const auto inkIn = [&](int y0, int y1) {
        size_t n = 0;
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < plot.width(); ++x) n += plot.at(x, y).r < 0.5f;
        return n;
    };
    EXPECT_GT(inkIn(57, 60), 20u) << "the first line's glyphs end at y 60";
    EXPECT_GT(inkIn(64, 78), 100u) << "a second line";
}

// A line too wide breaks after its last ", " or "; " that lets the first part fit; one that fits, or has no
// such break, stays whole.
TEST(Pictures, BreakToFitBreaksAtTheLastSeparatorThatFits) {
    const std::string text = "ASET view, lit = bright or low light; scintillation 7.20 +- 0.18 % per frame";
    EXPECT_EQ(breakToFit(text, 2, 630),
              std::make_pair(std::string("ASET view, lit = bright or low light;"),
                             std::string("scintillation 7.20 +- 0.18 % per frame")));
    EXPECT_EQ(
        breakToFit(text, 2, 150),
        std::make_pair(std::string("ASET view,"),
                       std::string("lit = bright or low light; scintillation 7.20 +- 0.18 % per frame")));
    EXPECT_EQ(breakToFit(text, 2, 2000).second, "");
    EXPECT_EQ(breakToFit("no separator here at all", 2, 50).first, "no separator here at all");
    // A verdict breaks after its colon rather than inside its list.
    EXPECT_EQ(breakToFit("dark at 0, 90, 180 and 270 deg of a turn: doubly refracting", 2, 630),
              std::make_pair(std::string("dark at 0, 90, 180 and 270 deg of a turn:"),
                             std::string("doubly refracting")));
}

// Every line wrapToFit gives fits the width, broken after ", ", "; " or ": " where one lets it fit and else
// at a space; the lines joined by spaces are the text again. Without spaces as breaks, a part too wide stays
// whole on a line of its own, the parts after it wrapped (a long stone name took the rest of a face-up
// picture's title with it, all shrunk to fit).
TEST(Pictures, WrapToFitBreaksEveryLineToTheWidth) {
    const std::string text =
        "through the table: median 0.088 mm (quartiles 0.081-0.097), 1.35 % of the girdle, "
        "12.1 arcmin through a 10x loupe; through the whole crown the median is 0.057 mm "
        "(quartiles 0.030-0.081), seen 45 deg from the optic axis";
    const std::vector<std::string> lines = wrapToFit(text, 2, 710);
    ASSERT_GE(lines.size(), 4u);
    std::string joined;
    for (const std::string& line : lines) {
        EXPECT_LE(textWidth(line, 2), 710) << line;
        joined += (joined.empty() ? "" : " ") + line;
    }
    EXPECT_EQ(joined, text);
    EXPECT_EQ(lines[0], "through the table: median 0.088 mm (quartiles 0.081-0.097),");
    EXPECT_EQ(lines[3], "0.030-0.081), seen 45 deg from the optic axis") << "broken at a space";
    const std::vector<std::string> parts = wrapToFit(text, 2, 710, false);
    ASSERT_GE(parts.size(), 2u);
    EXPECT_EQ(parts[parts.size() - 2],
              "through the whole crown the median is 0.057 mm (quartiles 0.030-0.081),");
    EXPECT_EQ(parts.back(), "seen 45 deg from the optic axis");
    EXPECT_EQ(wrapToFit("", 2, 100).size(), 0u);
}

TEST(Pictures, PngSignatureAndSize) {
    Image image(20, 10, {0.5f, 0.25f, 1});
    drawText(image, 1, 1, "42%", 1, {0, 0, 0});
    EXPECT_EQ(pngSize(encodePng(image)), std::make_pair(20u, 10u));
}

TEST(Spectrum, BandsAddUpToWhite) {
    for (int count : {1, 3, 4, 16}) {
        const SpectralBands bands(count);
        Vec3 sum;
        for (int b = 0; b < count; ++b) sum += bands.colour(b);
        EXPECT_NEAR(sum.x, 1, 1e-9);
        EXPECT_NEAR(sum.y, 1, 1e-9);
        EXPECT_NEAR(sum.z, 1, 1e-9);
        EXPECT_GE(bands.wavelength(0, 0), kMinWavelength);
        EXPECT_LE(bands.wavelength(count - 1, 1), kMaxWavelength);
    }
    const SpectralBands four(4);
    EXPECT_GT(four.colour(0).z, four.colour(0).x);  // the short-wave band is blue
    EXPECT_GT(four.colour(3).x, four.colour(3).z);  // the long-wave band is red
}

TEST(Spectrum, MatchingFunctionsPeakWhereCieSays) {
    // CIE 1931: y peaks at 555 nm with 1.0; x at about 600 nm with 1.06; z at about 445 nm with 1.78.
    EXPECT_NEAR(cieXyz(555).y, 1.0, 0.02);
    EXPECT_NEAR(cieXyz(600).x, 1.06, 0.03);
    EXPECT_NEAR(cieXyz(445).z, 1.78, 0.06);
    // Photons spread evenly over the visible range average to white.
    Vec3 sum;
    const int n = 4000;
    for (int i = 0; i < n; ++i)
        sum += photonColour(kMinWavelength + (i + 0.5) * (kMaxWavelength - kMinWavelength) / n);
    EXPECT_NEAR(sum.x / n, 1, 0.01);
    EXPECT_NEAR(sum.y / n, 1, 0.01);
    EXPECT_NEAR(sum.z / n, 1, 0.01);
}

// A diffuse floor under a collimated beam of irradiance E and no stone: N photons of power E A / N land
// uniformly on an area A; the k-nearest estimate at any inner point has relative standard deviation about
// 1 / sqrt(k), so the mean over Q well-separated points lies within 4 / sqrt(k Q) of E.
TEST(PhotonMapIrradiance, OpenFloorMatchesAnalyticValue) {
    const double E = 2.5, side = 2, area = side * side;
    const Vec3 beam = normalize(Vec3{0.3, 0, -1});
    const double floorE = E * -beam.z;  // irradiance on the floor
    const size_t n = 400'000;
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-side / 2, side / 2);
    std::vector<Photon> photons;
    for (size_t i = 0; i < n; ++i)
        photons.push_back(Photon::make({u(rng), u(rng), 0}, float(floorE * area / n), beam));
    const PhotonMap map(std::move(photons), 2);
    constexpr int k = 100;
    std::vector<Neighbor> buffer(k);
    GatherState state;
    double sum = 0;
    int queries = 0;
    for (int i = -4; i <= 4; ++i) {
        for (int j = -4; j <= 4; ++j) {
            sum += map.irradiance({0.18 * i, 0.18 * j, 0}, {0, 0, 1}, buffer, state);
            ++queries;
        }
    }
    const double mean = sum / queries;
    EXPECT_NEAR(mean / floorE, 1.0, 4 / std::sqrt(double(k) * queries));
    // Photons arriving from below the surface do not light it.
    EXPECT_EQ(map.irradiance({0, 0, 0}, {0, 0, -1}, buffer, state), 0.0);
}

// The scene's photon power in the units of its direct light: the photons of a collimated beam carry the
// beam's unit irradiance over the disc they are aimed through.
TEST(Scene, PhotonPowerMatchesTheBeam) {
    TraceSettings t = smallTrace(1);
    const Scene scene(roundBrilliant(), t);
    const LightModel light(t.light, roundBrilliant());
    EXPECT_NEAR(scene.photonPower(1000) * 1000, kPi * light.discRadius() * light.discRadius(), 1e-12);
    // The open floor beside the stone gets the whole beam; the floor straight under it is in its shadow.
    Rng rng(1, 2);
    const double r = roundBrilliant().bounds.hi.x;
    const double floorZ = roundBrilliant().bounds.lo.z;
    EXPECT_DOUBLE_EQ(scene.directIrradiance({3 * r, 0, floorZ}, rng), 1.0);
    EXPECT_DOUBLE_EQ(scene.directIrradiance({0.3 * r, 0.1 * r, floorZ}, rng), 0.0);
}

TEST(RenderSettings, JsonRoundTripAndStrictErrors) {
    RenderSettings s;
    s.width = 123;
    s.camera.fovDeg = 33;
    const RenderSettings back = RenderSettings::fromJson(toJson(s));
    EXPECT_EQ(back.width, 123);
    EXPECT_EQ(back.camera.fovDeg, 33);
    auto message = [](const char* text) {
        try {
            RenderSettings::fromJson(nlohmann::json::parse(text));
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(message(R"({"width": "wide"})"), "render.width must be an integer between 16 and 4096");
    EXPECT_EQ(message(R"({"width": 8})"), "render.width must be an integer between 16 and 4096");
    EXPECT_EQ(message(R"({"height": 40.5})"), "render.height must be an integer between 16 and 4096");
    EXPECT_EQ(message(R"({"samples": 0})"), "render.samples must be an integer between 1 and 256");
    EXPECT_EQ(message(R"({"colour": 1})"), "unknown field 'render.colour'");
    EXPECT_EQ(message(R"({"camera": {"zoom": 2}})"), "unknown field 'render.camera.zoom'");
    EXPECT_EQ(message(R"({"camera": 5})"), "render.camera must be a JSON object");
    EXPECT_EQ(message(R"({"camera": {"fov_deg": 0}})"),
              "render.camera.fov_deg must be a number above 0 up to 120");
    EXPECT_EQ(message(R"({"camera": {"elevation_deg": true}})"),
              "render.camera.elevation_deg must be a number from -90 to 90");
    EXPECT_EQ(message(R"({"map_photons": -5})"),
              "render.map_photons must be an integer between 1000 and 10000000000");
    EXPECT_EQ(message(R"([1, 2])"), "render must be a JSON object");
    EXPECT_EQ(message(R"({"width": 1e2, "max_depth": 4})"), "no error");
}

}  // namespace
}  // namespace facetlight
