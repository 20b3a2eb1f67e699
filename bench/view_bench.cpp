// The viewer's views against thread count: a 400 x 400 ASET picture of the default round brilliant (default
// ASET settings: 8 view rays per pixel) and a 21-frame tilt series at 320 x 320 (-10..+10 deg), each with the
// pictures encoded as the study encodes them (aset.png; the frames' animated WebP and the chart). Medians of
// the runs, wall and CPU seconds side by side.
//   view_bench [runs]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "bench_timing.h"
#include "cuts/mesh_resolver.h"
#include "pictures/aset_picture.h"
#include "pictures/tilt_chart.h"
#include "pictures/webp_animation.h"
#include "render/aset.h"
#include "render/tilt_series.h"
#include "scene/scene.h"

using namespace facetlight;

using bench::median;
using bench::seconds;

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    const Stone stone = resolveStone("round_brilliant");
    const AsetSettings aset;
    TiltSeriesSettings tilt;
    tilt.maxDeg = 10;
    std::printf("round brilliant, %d view rays per pixel; median of %d runs\n", aset.samples, runs);
    std::printf("| threads | ASET 400x400 s | ASET CPU s | tilt series 21 x 320x320 s | tilt CPU s |\n");
    std::printf("|---|---|---|---|---|\n");
    for (int threads : {1, 2}) {
        TraceSettings trace;
        trace.threads = threads;
        const Scene scene(stone, trace);
        const TraceBase traced(scene, trace);
        std::vector<double> asetWall, asetCpu, tiltWall, tiltCpu;
        for (int r = 0; r < runs; ++r) {
            auto t0 = std::chrono::steady_clock::now();
            std::clock_t c0 = std::clock();
            const AsetView view = asetView(traced, CameraSettings{}, 400, 400, aset, threads, trace.seed);
            const std::string png = encodePng(asetPicture(view, aset, "ASET"));
            asetWall.push_back(seconds(t0));
            asetCpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);

            t0 = std::chrono::steady_clock::now();
            c0 = std::clock();
            const TiltSeries series = tiltSeries(traced, CameraSettings{}, 320, 320, aset, tilt);
            std::vector<Image> frames;
            for (const TiltFrame& f : series.frames) {
                frames.push_back(asetPicture(f.view, aset, "tilt " + std::to_string(f.tiltDeg)));
            }
            const std::string webp = encodeAnimatedWebp(frames, 120);
            const std::string chart = encodePng(tiltChart(series, "tilt"));
            tiltWall.push_back(seconds(t0));
            tiltCpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
        }
        std::printf("| %d | %.3f | %.3f | %.2f | %.2f |\n", threads, median(asetWall), median(asetCpu),
                    median(tiltWall), median(tiltCpu));
    }
    return 0;
}
