// The viewer figures against thread count (docs/performance.md, "Viewer figures"): the office and spot
// set-ups of the default round brilliant at the default viewer settings (every tilt and turn averaged), with
// the largest standard error among the figures; and a 17 x 16 crown-pavilion map of them as `facetlight sweep
// round_brilliant --vary pavilion=37:45:0.5 --vary crown=25:40:1` traces it (200 000 photons a point beside
// the viewer's rays). Medians of the runs, wall and CPU seconds. Targets: under 5 s and 3 minutes at 2 threads.
//   viewer_bench [runs]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include "bench_timing.h"
#include "cuts/mesh_resolver.h"
#include "sweep/sweep_run.h"
#include "viewer/viewer_figures.h"

using namespace facetlight;

using bench::median;
using bench::seconds;

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    const Stone stone = resolveStone("round_brilliant");
    TraceSettings trace;
    std::printf("round brilliant, %llu face-up points x %d looks, %llu lamp photons; median of %d runs\n",
                (unsigned long long)trace.viewer.office.points, 2 * trace.viewer.positions(),
                (unsigned long long)trace.viewer.spot.photons, runs);
    std::printf("| threads | one stone s | CPU s | largest standard error |\n|---|---|---|---|\n");
    for (int threads : {1, 2}) {
        trace.threads = threads;
        std::vector<double> wall, cpu;
        double largest = 0;
        for (int r = 0; r < runs; ++r) {
            const auto t0 = std::chrono::steady_clock::now();
            const std::clock_t c0 = std::clock();
            const ViewerFigures f = viewStone(stone, trace);
            wall.push_back(seconds(t0));
            cpu.push_back(double(std::clock() - c0) / CLOCKS_PER_SEC);
            for (const ViewerFigureInfo& info : kViewerFigures)
                largest = std::max(largest, (f.*info.get)().stderr);
        }
        std::printf("| %d | %.2f | %.2f | %.4f |\n", threads, median(wall), median(cpu), largest);
    }

    SweepPlan plan;
    plan.shape = "round_brilliant";
    plan.axes = {parseSweepAxis("pavilion=37:45:0.5"), parseSweepAxis("crown=25:40:1")};
    plan.trace.photons = 200000;
    std::printf("\ncrown-pavilion map, %zu points with the viewer figures\n", plan.pointCount());
    std::printf("| threads | map s | points/second |\n|---|---|---|\n");
    for (int threads : {1, 2}) {
        plan.trace.threads = threads;
        std::vector<double> wall;
        for (int r = 0; r < runs; ++r) {
            RunControl control;
            wall.push_back(runSweep(plan, control).seconds);
        }
        std::printf("| %d | %.1f | %.2f |\n", threads, median(wall), double(plan.pointCount()) / median(wall));
    }
}
