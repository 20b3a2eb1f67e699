// Render time against thread count: the 400 x 400 face-up picture of the default round brilliant with
// caustics and dispersion (200 000 map photons, 4 samples per pixel), each phase timed separately and the
// whole job as the `render` command runs it after the statistics trace. Medians of 5 runs, side by side.
// Then the fire picture (render/fire_picture.h, 24 wavelengths a pixel) beside the render at the same size,
// the two run alternately in one process so that the machine's load falls on both alike.
// A SIMD target (e.g. AVX2) limits the dispatch to it, to measure a lower target on a better CPU.
//   render_bench [runs] [simd target]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "bench_timing.h"
#include "cuts/mesh_resolver.h"
#include "photonmap/floor_photons.h"
#include "photonmap/photon_map.h"
#include "render/fire_picture.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "trace/photon_tracer.h"
#include "util/simd_target.h"

using namespace facetlight;

using bench::median;
using bench::seconds;

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    if (argc > 2) limitSimdTarget(argv[2]);
    std::printf("SIMD target: %s\n", simdTarget().c_str());
    const Stone stone = resolveStone("round_brilliant");
    const RenderSettings settings;  // 400 x 400, 4 samples, 200 000 map photons, face-up
    std::printf("round brilliant, %d x %d, %d samples, %llu map photons, dispersion on; median of %d runs\n",
                settings.width, settings.height, settings.samples, (unsigned long long)settings.mapPhotons,
                runs);
    // CPU seconds (all threads) beside wall seconds: on a shared machine the wall time also counts waiting.
    std::printf(
        "| threads | photon pass s | tree build s | render s | render CPU s | total s | render speed-up |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    double renderOne = 0;
    for (int threads : {1, 2}) {
        TraceSettings trace;
        trace.threads = threads;
        const Scene scene(stone, trace);
        const TraceBase traced(scene, trace);
        std::vector<double> pass, build, draw, drawCpu, total;
        for (int r = 0; r < runs; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            FloorPhotons photons = traceFloorPhotons(traced, settings.mapPhotons, threads);
            pass.push_back(seconds(t0));
            const auto t1 = std::chrono::steady_clock::now();
            const PhotonMap caustics(std::move(photons.caustic), threads);
            build.push_back(seconds(t1));
            const auto t2 = std::chrono::steady_clock::now();
            const std::clock_t c2 = std::clock();
            const RenderedImage image = render(scene, caustics, settings, threads, trace.seed);
            draw.push_back(seconds(t2));
            drawCpu.push_back(double(std::clock() - c2) / CLOCKS_PER_SEC);
            total.push_back(seconds(t0));
        }
        if (threads == 1) renderOne = median(draw);
        std::printf("| %d | %.3f | %.3f | %.3f | %.3f | %.3f | %.2f |\n", threads, median(pass),
                    median(build), median(draw), median(drawCpu), median(total), renderOne / median(draw));
    }

    const FirePictureSettings fire;
    std::printf("\nfire picture (%d wavelengths a pixel) against the render, 2 threads, alternating runs\n",
                fire.wavelengths);
    std::printf("| picture | s | CPU s |\n|---|---|---|\n");
    TraceSettings trace;
    trace.threads = 2;
    const Scene scene(stone, trace);
    const TraceBase traced(scene, trace);
    FloorPhotons photons = traceFloorPhotons(traced, settings.mapPhotons, trace.threads);
    const PhotonMap caustics(std::move(photons.caustic), trace.threads);
    std::vector<double> plain, plainCpu, spectral, spectralCpu;
    for (int r = 0; r < runs; ++r) {
        auto t = std::chrono::steady_clock::now();
        std::clock_t c = std::clock();
        const RenderedImage image = render(scene, caustics, settings, trace.threads, trace.seed);
        plain.push_back(seconds(t));
        plainCpu.push_back(double(std::clock() - c) / CLOCKS_PER_SEC);
        t = std::chrono::steady_clock::now();
        c = std::clock();
        const FirePicture picture = firePicture(scene, settings, fire, trace.threads, trace.seed);
        spectral.push_back(seconds(t));
        spectralCpu.push_back(double(std::clock() - c) / CLOCKS_PER_SEC);
    }
    std::printf("| render (%d samples) | %.3f | %.3f |\n", settings.samples, median(plain), median(plainCpu));
    std::printf("| fire picture | %.3f | %.3f |\n", median(spectral), median(spectralCpu));
    std::printf("fire picture / render: %.2f (wall), %.2f (CPU)\n", median(spectral) / median(plain),
                median(spectralCpu) / median(plainCpu));
    return 0;
}
