// Render time against thread count: the 400 x 400 face-up picture of the default round brilliant with
// caustics and dispersion (200 000 map photons, 4 samples per pixel), each phase timed separately and the
// whole job as the `render` command runs it after the statistics trace. Medians of 5 runs, side by side.
//   render_bench [runs]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "intersect/scene.h"
#include "io/mesh_resolver.h"
#include "photonmap/floor_photons.h"
#include "photonmap/photon_map.h"
#include "render/renderer.h"
#include "trace/photon_tracer.h"

using namespace facetlight;

namespace {

double seconds(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
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
        std::vector<double> pass, build, draw, drawCpu, total;
        for (int r = 0; r < runs; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            FloorPhotons photons = traceFloorPhotons(scene, settings.mapPhotons, threads);
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
    return 0;
}
