#include "render/tilt_series.h"

#include <gtest/gtest.h>
#include <webp/demux.h>

#include <cmath>
#include <memory>

#include "cuts/cut_library.h"
#include "pictures/aset_picture.h"
#include "pictures/tilt_chart.h"
#include "pictures/webp_animation.h"
#include "scene/scene.h"
#include "study/study.h"
#include "support/fixtures.h"
#include "util/error.h"

using namespace facetlight;

namespace {

Stone slab() {
    PolygonMesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({20.0 * (i & 1), 20.0 * ((i >> 1) & 1), double((i >> 2) & 1)});
    m.polygons = {{{0, 2, 3, 1}, "bottom"}, {{4, 5, 7, 6}, "top"},  {{0, 1, 5, 4}, "front"},
                  {{2, 6, 7, 3}, "back"},   {{0, 4, 6, 2}, "left"}, {{1, 3, 7, 5}, "right"}};
    return Stone::build(m, "slab");
}

TraceSettings diamond() {
    TraceSettings s;
    s.dispersion = false;
    s.threads = 2;
    return s;
}

struct Decoded {
    int frames = 0, width = 0, height = 0;
};

Decoded decode(const std::string& webp) {
    WebPData data{reinterpret_cast<const uint8_t*>(webp.data()), webp.size()};
    WebPAnimDecoderOptions options;
    EXPECT_TRUE(WebPAnimDecoderOptionsInit(&options));
    const std::unique_ptr<WebPAnimDecoder, void (*)(WebPAnimDecoder*)> decoder(
        WebPAnimDecoderNew(&data, &options), WebPAnimDecoderDelete);
    if (!decoder) return {};
    WebPAnimInfo info;
    EXPECT_TRUE(WebPAnimDecoderGetInfo(decoder.get(), &info));
    Decoded d{0, int(info.canvas_width), int(info.canvas_height)};
    while (WebPAnimDecoderHasMoreFrames(decoder.get())) {
        uint8_t* pixels;
        int timestamp;
        if (!WebPAnimDecoderGetNext(decoder.get(), &pixels, &timestamp)) break;
        ++d.frames;
    }
    EXPECT_EQ(d.frames, int(info.frame_count));
    return d;
}

}  // namespace

// Face-up, a slab shows the head's reflection or leaks everywhere; tilted by 3 deg its mirror direction moves
// by 6 deg, still inside the 15-deg head cone: no pixel is ever lit, none switches.
TEST(TiltSeries, SlabDoesNotSparkle) {
    const Stone stone = slab();
    CameraSettings camera;
    camera.distance = 10;
    camera.fovDeg = 2;
    TiltSeriesSettings tilt;
    tilt.maxDeg = 3;
    AsetSettings aset;
    aset.samples = 4;
    const Scene scene(stone, diamond());
    const TraceBase trace(scene, diamond());
    const TiltSeries series = tiltSeries(trace, camera, 32, 32, aset, tilt);
    ASSERT_EQ(series.frames.size(), 7u);
    EXPECT_EQ(series.pixelPairs, 6u * 32 * 32);
    EXPECT_EQ(series.switched, 0u);
    EXPECT_EQ(series.scintillation().share, 0);
    for (const TiltFrame& f : series.frames) EXPECT_EQ(f.lightReturn.share, 0);
}

TEST(TiltSeries, BrilliantSparkles) {
    TiltSeriesSettings tilt;
    tilt.maxDeg = 2;
    AsetSettings aset;
    aset.samples = 2;
    const Scene scene(test::roundBrilliant(), diamond());
    const TraceBase trace(scene, diamond());
    const TiltSeries series = tiltSeries(trace, CameraSettings{}, 64, 64, aset, tilt);
    ASSERT_EQ(series.frames.size(), 5u);
    EXPECT_EQ(series.frames.front().tiltDeg, -2);
    EXPECT_GT(series.scintillation().share, 0.02);
    EXPECT_LT(series.scintillation().share, 0.8);
    EXPECT_GT(series.frames[2].lightReturn.share, 0.3);
    EXPECT_FALSE(encodePng(tiltChart(series, "chart")).empty());
}

// Whether two shares agree within 4 combined standard errors.
bool agree(const AsetShare& p, const AsetShare& q) {
    return std::fabs(p.share - q.share) <= 4 * std::hypot(p.standardError, q.standardError);
}

// The frames' class shares on which two series of as many frames disagree.
int disagreements(const TiltSeries& p, const TiltSeries& q) {
    int n = 0;
    for (size_t k = 0; k < p.frames.size(); ++k)
        for (int c = 0; c < kAsetClasses; ++c)
            n += !agree(p.frames[k].view.share(AsetClass(c)), q.frames[k].view.share(AsetClass(c)));
    return n;
}

// Rocking about y a stone turned 90 deg about z is rocking the stone itself about x: an oval (no 90-deg
// symmetry) shows the same shares frame by frame and the same scintillation, within their errors; rocked
// about x instead, the turned oval differs (the check can fail). The camera is far and narrow, so the view is
// nearly parallel and the turned stone's other girdle width (the camera's unit) does not matter.
TEST(TiltSeries, TheAxisTurnsWithTheStone) {
    const PolygonMesh mesh = makeCut("oval");
    PolygonMesh turned = mesh;
    for (Vec3& v : turned.vertices) v = {-v.y, v.x, v.z};
    StoneOptions raw;
    raw.standardFrame = false;  // the standard frame would turn the oval's long axis back onto x
    const Stone oval = Stone::build(mesh, "oval", raw), ovalTurned = Stone::build(turned, "turned oval", raw);
    const CameraSettings camera{.distance = 200, .fovDeg = 0.45};
    const AsetSettings aset{.samples = 4};
    const TiltSeriesSettings aboutX{.maxDeg = 8, .stepDeg = 4},
        aboutY{.maxDeg = 8, .stepDeg = 4, .axisDeg = 90};
    const Scene scene(oval, diamond()), turnedScene(ovalTurned, diamond());
    const TraceBase trace(scene, diamond()), turnedTrace(turnedScene, diamond());
    const TiltSeries a = tiltSeries(trace, camera, 96, 96, aset, aboutX);
    const TiltSeries b = tiltSeries(turnedTrace, camera, 96, 96, aset, aboutY);
    const TiltSeries wrong = tiltSeries(turnedTrace, camera, 96, 96, aset, aboutX);
    ASSERT_EQ(a.frames.size(), 5u);
    ASSERT_EQ(b.frames.size(), 5u);
    EXPECT_EQ(disagreements(a, b), 0);
    EXPECT_TRUE(agree(a.scintillation(), b.scintillation()))
        << a.scintillation().share << " against " << b.scintillation().share;
    EXPECT_GE(disagreements(a, wrong), 4) << "rocking the turned oval about x should look different";
    EXPECT_FALSE(agree(a.scintillation(), wrong.scintillation()))
        << a.scintillation().share << " against " << wrong.scintillation().share;
}

// A render with a tilt series returns an animation that decodes to one frame per tilt, and the figures.
TEST(TiltSeries, StudyWritesAnAnimationThatDecodes) {
    StudySettings settings;
    settings.trace = diamond();
    settings.trace.photons = 20000;
    RenderSettings render;
    render.width = render.height = 48;
    render.samples = 1;
    render.mapPhotons = 2000;
    settings.render = render;
    settings.aset = AsetSettings{};
    settings.aset->samples = 2;
    settings.tiltSeries = TiltSeriesSettings{};
    settings.tiltSeries->maxDeg = 3;
    settings.tiltSeries->stepDeg = 1.5;
    RunControl control;
    const StudyResult result = runStudy(test::roundBrilliant(), settings, control);
    const Decoded d = decode(result.file("tilt.webp"));
    EXPECT_EQ(d.frames, 5);
    EXPECT_GE(d.width, 48);
    EXPECT_EQ(result.stats["tilt_series"]["frames"].size(), 5u);
    EXPECT_EQ(result.stats["aset"]["shares"].size(), 5u);
    EXPECT_FALSE(result.file("aset.png").empty());
    EXPECT_FALSE(result.file("tilt.png").empty());
    EXPECT_EQ(control.done(), control.total());

    settings.render.reset();
    EXPECT_THROW(runStudy(test::roundBrilliant(), settings, control), Error);
}

// The encoder merges a frame identical to the one before into it (the tilt frames differ by their titles).
TEST(WebpAnimation, FramesOfOneSize) {
    const Image a(20, 10), b(20, 10, {1, 0, 0}), c(10, 10);
    EXPECT_EQ(decode(encodeAnimatedWebp(std::vector<Image>{a, b, a}, 100)).frames, 3);
    EXPECT_THROW(encodeAnimatedWebp(std::vector<Image>{a, c}, 100), Error);
}
