// A crown-pavilion map as `facetlight sweep round_brilliant --vary pavilion=37:45:0.5 --vary crown=25:40:1
// --photons 2e5 --no-view` traces it: 17 x 16 points of 200 000 photons, collimated light, dispersion on,
// each design built once, no viewer figures (bench/viewer_bench.cpp times those). Prints the wall time of the whole sweep (designs built and points traced) at 1 and 2 threads,
// median of the runs. The target: under 60 s at 2 threads.
//   sweep_bench [runs]
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "sweep/sweep_run.h"

using namespace facetlight;

int main(int argc, char** argv) {
    const int runs = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    SweepPlan plan;
    plan.shape = "round_brilliant";
    plan.axes = {parseSweepAxis("pavilion=37:45:0.5"), parseSweepAxis("crown=25:40:1")};
    plan.trace.photons = 200000;
    plan.trace.viewer.enabled = false;
    std::printf(
        "round brilliant, pavilion 37-45 by 0.5 x crown 25-40 by 1 = %zu points of %llu photons; median "
        "of %d runs\n",
        plan.pointCount(), (unsigned long long)plan.trace.photons, runs);
    std::printf("%8s %12s %16s\n", "threads", "seconds", "points/second");
    for (int threads : {1, 2}) {
        plan.trace.threads = threads;
        std::vector<double> seconds;
        for (int r = 0; r < runs; ++r) {
            RunControl control;
            seconds.push_back(runSweep(plan, control).seconds);
        }
        std::sort(seconds.begin(), seconds.end());
        const double median = seconds[seconds.size() / 2];
        std::printf("%8d %12.2f %16.1f\n", threads, median, double(plan.pointCount()) / median);
    }
}
