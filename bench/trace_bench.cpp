// Stats-only photon tracing of a 57-facet round brilliant (collimated light straight down, no dispersion),
// in photons per second for 1 and 2 threads; the same with dispersion, and the shipped 121-facet brilliant.
// A fire trace against the plain one, interleaved (BM_FireVsPlainBrilliant57; BM_FireVsPlainNoDispersion
// without dispersion). Figures go to docs/performance.md ("Photon tracing", "Fire trace"). --simd=NAME (e.g.
// AVX2, SSE4) limits the dispatch to that SIMD target, to measure a lower target on a better CPU;
// --simd=list prints the targets this CPU runs.
// scripts/perf-figures runs it for every target and two builds, interleaved.
//   build-*/bin/bench_trace [--simd=AVX2] --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "bench_timing.h"
#include "geometry/halfspace.h"
#include "intersect/convex_intersector.h"
#include "io/mesh_io.h"
#include "optics/birefringence.h"
#include "optics/material.h"
#include "support/many_facet_stones.h"
#include "trace/photon_tracer.h"
#include "util/simd_target.h"

using namespace facetlight;

namespace {

// Tolkowsky-like proportions (girdle diameter 1, knife-edge girdle): table 53%, crown 34.5 deg, pavilion
// 40.75 deg; stars, upper and lower halves at the usual azimuths with slopes a few degrees off the mains.
Stone builtBrilliant() {
    std::vector<NamedPlane> planes;
    const double tableZ = (1 - 0.53) / 2 * std::tan(radians(34.5));
    planes.push_back({{{0, 0, 1}, tableZ}, "table"});
    auto add = [&](double azimuthDeg, double slopeDeg, bool crown, const Vec3& through,
                   const std::string& name) {
        const double a = radians(azimuthDeg), s = radians(slopeDeg);
        const Vec3 n = normalize(
            Vec3{std::sin(s) * std::cos(a), std::sin(s) * std::sin(a), (crown ? 1 : -1) * std::cos(s)});
        planes.push_back({{n, dot(n, through)}, name});
    };
    auto girdlePoint = [](double azimuthDeg) {
        return Vec3{0.5 * std::cos(radians(azimuthDeg)), 0.5 * std::sin(radians(azimuthDeg)), 0};
    };
    for (int k = 0; k < 8; ++k) {
        const double main = 45.0 * k, star = main + 22.5;
        add(main, 34.5, true, girdlePoint(main), "bezel_" + std::to_string(k));
        const double edge = 0.53 / 2 * std::cos(radians(22.5));
        add(star, 22.0, true, {edge * std::cos(radians(star)), edge * std::sin(radians(star)), tableZ},
            "star_" + std::to_string(k));
        add(main, 40.75, false, girdlePoint(main), "pavilion_main_" + std::to_string(k));
        for (int side : {-1, 1}) {
            const double half = main + side * 11.25;
            const std::string tag = std::to_string(2 * k + (side > 0));
            add(half, 40.0, true, girdlePoint(half), "upper_half_" + tag);
            add(half, 42.0, false, girdlePoint(half), "lower_half_" + tag);
        }
    }
    return Stone::build(intersectHalfSpaces(planes), "round_brilliant");
}

const Stone& brilliant() {
    static const Stone stone = builtBrilliant();
    return stone;
}

// The shipped round brilliant (meshes/round_brilliant.obj, with a faceted girdle), when the tree has one.
const Stone* shippedBrilliant() {
    static const std::optional<Stone> stone = []() -> std::optional<Stone> {
        const std::string path = std::string(FACETLIGHT_SOURCE_DIR) + "/meshes/round_brilliant.obj";
        if (!std::filesystem::exists(path)) return std::nullopt;
        return loadStone(path);
    }();
    return stone ? &*stone : nullptr;
}

// The shipped brilliant, or null with the benchmark marked skipped.
const Stone* shippedBrilliantOrSkip(benchmark::State& state) {
    const Stone* stone = shippedBrilliant();
    if (!stone) state.SkipWithError("meshes/round_brilliant.obj not found");
    return stone;
}

double threadCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

void traceStats(benchmark::State& state, const Stone& stone, bool dispersion = false) {
    TraceSettings settings;
    settings.photons = 4'000'000;
    settings.threads = int(state.range(0));
    settings.dispersion = dispersion;
    const Scene scene(stone, settings);
    const TraceBase traced(scene, settings);
    uint64_t interfaces = 0;
    const double cpuStart = processCpuSeconds();
    for (auto _ : state) {
        FacetStats stats(stone.facets.size());
        traceBlocks(traced, 0, blockCount(settings.photons), settings.threads, stats);
        benchmark::DoNotOptimize(stats.exited);
        interfaces = stats.hit + stats.exited;
        for (const FacetCounts& f : stats.facets) interfaces += f.internalReflections;
    }
    const double photons = double(settings.photons) * double(state.iterations());
    state.counters["photons_per_s"] = benchmark::Counter(photons, benchmark::Counter::kIsRate);
    // Per CPU second of all the trace's threads: what a core does, whatever else the machine runs.
    state.counters["photons_per_cpu_s"] = photons / (processCpuSeconds() - cpuStart);
    // Surface interactions (entry, internal reflections, exit) per photon drawn: the work per photon.
    state.counters["interfaces_per_photon"] = double(interfaces) / double(settings.photons);
    state.counters["facets"] = double(stone.facets.size());
}

void BM_TraceBrilliant57(benchmark::State& state) {
    traceStats(state, brilliant());
}
BENCHMARK(BM_TraceBrilliant57)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);

// The same with dispersion, a job's default: each photon draws a wavelength and has its own index.
void BM_TraceBrilliant57Dispersion(benchmark::State& state) {
    traceStats(state, brilliant(), true);
}
BENCHMARK(BM_TraceBrilliant57Dispersion)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

void BM_TraceShippedBrilliant(benchmark::State& state) {
    if (const Stone* stone = shippedBrilliant()) {
        traceStats(state, *stone);
    } else {
        state.SkipWithError("meshes/round_brilliant.obj not found");
    }
}
BENCHMARK(BM_TraceShippedBrilliant)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MinTime(2.0);

// The shipped brilliant's crown and pavilion alone, meeting at a knife edge: its 57 planes without the 64 of
// the girdle. Against the shipped stone it shows what the girdle costs; against the built 57-facet brilliant,
// what the proportions cost (the paths differ).
void BM_TraceShippedWithoutGirdle(benchmark::State& state) {
    const Stone* stone = shippedBrilliantOrSkip(state);
    if (!stone) return;
    static const Stone knifeEdge = [&] {
        std::vector<NamedPlane> planes;
        for (const Facet& f : stone->facets) {
            if (f.region != Region::Girdle) planes.push_back({f.plane(), f.name});
        }
        return Stone::build(intersectHalfSpaces(planes), "round_brilliant_knife_edge");
    }();
    traceStats(state, knifeEdge);
}
BENCHMARK(BM_TraceShippedWithoutGirdle)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->MinTime(2.0);
// A fire trace (each photon also at the C, D and F lines, trace/fire_trace.h) against the plain trace it
// extends, 1 M photons each, timed alternately in each iteration so that a loaded machine slows both alike:
// the medians and their ratio (target: fire at most 3x plain, issue 32). BM_FireVsPlainBrilliant57 traces the
// dispersive job (a job's default).
void fireVsPlain(benchmark::State& state, bool dispersion) {
    TraceSettings plain;
    plain.photons = 1'000'000;
    plain.threads = int(state.range(0));
    plain.dispersion = dispersion;
    TraceSettings fire = plain;
    fire.fire.enabled = true;
    const Scene scene(brilliant(), plain);
    const TraceBase plainTrace(scene, plain), fireTrace(scene, fire);
    std::vector<double> seconds[2], cpuSeconds[2];  // plain, fire
    for (auto _ : state) {
        for (const TraceBase* base : {&plainTrace, &fireTrace}) {
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = processCpuSeconds();
            const TraceResult r = trace(*base);
            benchmark::DoNotOptimize(r.stats.exited);
            const int k = base == &fireTrace;
            cpuSeconds[k].push_back(processCpuSeconds() - cpuStart);
            seconds[k].push_back(bench::seconds(start));
        }
    }
    const double p = bench::median(seconds[0]), f = bench::median(seconds[1]);
    state.counters["plain_ms"] = 1e3 * p;
    state.counters["fire_ms"] = 1e3 * f;
    state.counters["fire_over_plain"] = f / p;
    // The same by CPU time, which a shared machine's other work disturbs less than the wall clock.
    state.counters["fire_over_plain_cpu"] = bench::median(cpuSeconds[1]) / bench::median(cpuSeconds[0]);
}
void BM_FireVsPlainBrilliant57(benchmark::State& state) {
    fireVsPlain(state, true);
}
BENCHMARK(BM_FireVsPlainBrilliant57)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(9);
// The same without dispersion (a design file's constant index, or --no-dispersion), where every band is the
// plain walk and the fire trace takes the plain walk's photons for its bands.
void BM_FireVsPlainNoDispersion(benchmark::State& state) {
    fireVsPlain(state, false);
}
BENCHMARK(BM_FireVsPlainNoDispersion)->Arg(1)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(9);

// Polarised tracing (issue 28) against the unpolarised trace of the same stone, the shipped brilliant on one
// thread, timed alternately in each iteration: diamond with polarization on, and sapphire, whose double
// refraction is traced with polarization on, against each material off (targets: at most 1.6x and 3x).
void BM_PolarizedVsPlainShipped(benchmark::State& state) {
    const Stone* stone = shippedBrilliantOrSkip(state);
    if (!stone) return;
    struct Run {
        const char* name;
        std::string material;
        PolarizationMode polarization;
        std::vector<double> seconds, cpu;  // wall and this thread's CPU time (the trace's one worker)
    };
    std::vector<Run> runs{{"diamond_off", "diamond", PolarizationMode::Off, {}, {}},
                          {"diamond_on", "diamond", PolarizationMode::On, {}, {}},
                          {"sapphire_off", "sapphire", PolarizationMode::Off, {}, {}},
                          {"sapphire_on", "sapphire", PolarizationMode::On, {}, {}}};
    for (auto _ : state) {
        for (Run& run : runs) {
            TraceSettings settings;
            settings.photons = run.polarization == PolarizationMode::On && run.material == "sapphire" ? 100'000
                                                                                                     : 400'000;
            settings.material = run.material;
            settings.polarization = run.polarization;
            const Scene scene(*stone, settings);
            const TraceBase base(scene, settings);
            const auto start = std::chrono::steady_clock::now();
            const double cpuStart = threadCpuSeconds();
            FacetStats stats(stone->facets.size());
            traceBlocks(base, 0, blockCount(settings.photons), 1, stats);
            benchmark::DoNotOptimize(stats.exited);
            const double perM = 1e6 / double(settings.photons);
            run.seconds.push_back(bench::seconds(start) * perM);
            run.cpu.push_back((threadCpuSeconds() - cpuStart) * perM);
        }
    }
    for (const Run& run : runs) state.counters[std::string(run.name) + "_s_per_M"] = bench::median(run.seconds);
    auto ratio = [&](int on, int off, bool cpu) {
        return cpu ? bench::median(runs[on].cpu) / bench::median(runs[off].cpu)
                   : bench::median(runs[on].seconds) / bench::median(runs[off].seconds);
    };
    state.counters["polarized_over_plain"] = ratio(1, 0, false);
    state.counters["birefringent_over_plain"] = ratio(3, 2, false);
    // The same by CPU time, steadier where other work shares the machine.
    state.counters["polarized_over_plain_cpu"] = ratio(1, 0, true);
    state.counters["birefringent_over_plain_cpu"] = ratio(3, 2, true);
}
BENCHMARK(BM_PolarizedVsPlainShipped)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);

// One crystal interface (optics/birefringence.h, issue 28), the doubly refracting trace's main cost: 20 000
// random incidences at 589 nm on sapphire with a random optic axis (crystal 0), or on topaz (1) or peridot
// (2) with random principal axes, entering from air (0) or leaving from inside as either of the crystal's
// waves (1); medians of 5 passes in thread CPU nanoseconds a call (the machine is shared).
void BM_CrystalInterface(benchmark::State& state) {
    const bool leaving = state.range(0) == 1;
    const char* names[] = {"sapphire", "topaz", "peridot"};
    const char* name = names[state.range(1)];
    const std::array<double, 3> n = Material::byName(name).principalIndices(Material::kSodiumD);
    std::mt19937_64 rng(1);
    std::normal_distribution<double> g;
    auto unit = [&] { return normalize(Vec3{g(rng), g(rng), g(rng)}); };
    const UniaxialMedium crystal{n[0], n[2], unit()};
    const bool biaxial = state.range(1) > 0;
    BiaxialMedium biaxialCrystal{n[0], n[1], n[2]};
    if (biaxial) {
        biaxialCrystal.z = crystal.axis;
        biaxialCrystal.x = normalize(cross(biaxialCrystal.z, unit()));
        biaxialCrystal.y = cross(biaxialCrystal.z, biaxialCrystal.x);
    }
    struct Incidence {
        Vec3 direction, normal;
        PlaneWave wave;
    };
    std::vector<Incidence> incidences;
    while (incidences.size() < 20'000) {
        Incidence in{unit(), unit(), {}};
        const bool second = incidences.size() % 2;
        in.wave = biaxial  ? biaxialWave(biaxialCrystal, unit(), second ? WaveMode::Slow : WaveMode::Fast)
                  : second ? ordinaryWave(crystal, unit())
                           : extraordinaryWave(crystal, unit());
        if (leaving ? !(dot(in.wave.ray, in.normal) > 1e-6) : !(dot(in.direction, in.normal) < -1e-6))
            continue;
        incidences.push_back(in);
    }
    auto share = [&](const Incidence& in) {
        if (biaxial)
            return leaving ? leaveCrystal(biaxialCrystal, in.wave, in.normal).reflected[0].share[0]
                           : enterCrystal(biaxialCrystal, in.direction, in.normal).transmitted[0].share[0];
        return leaving ? leaveCrystal(crystal, in.wave, in.normal).reflected[0].share[0]
                       : enterCrystal(crystal, in.direction, in.normal).transmitted[0].share[0];
    };
    std::vector<double> ns;
    for (auto _ : state) {
        double sum = 0;
        const double start = threadCpuSeconds();
        for (const Incidence& in : incidences) sum += share(in);
        ns.push_back((threadCpuSeconds() - start) / double(incidences.size()) * 1e9);
        benchmark::DoNotOptimize(sum);
    }
    state.SetLabel(std::string(name) + (leaving ? " leaving" : " entering"));
    state.counters["ns_per_interface"] = bench::median(ns);
}
BENCHMARK(BM_CrystalInterface)
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

// The exit search's culling (issue 32) against the search over every plane, on stones of many facets
// without a round girdle (tests/support/many_facet_stones.h: a 304-facet briolette, a 217-facet step cut, a
// 240-facet oval checkerboard) and on the shipped brilliant, whose girdle skip is the same either way (its
// ratio shows the noise). 200 000 photons of hemisphere light with dispersion on one thread, the two searches
// timed alternately in each iteration, in the thread's CPU seconds (the machine is shared); medians (target:
// at least 2x on the many-facet stones, no slower on the brilliant).
void BM_CulledVsFullSearch(benchmark::State& state) {
    static const Stone briolette = test::briolette(), stepCut = test::stepCut217(),
                       checkerboard = test::checkerboard();
    const Stone* stones[] = {&briolette, &stepCut, &checkerboard, shippedBrilliant()};
    const Stone* stone = stones[state.range(0)];
    if (!stone) {
        state.SkipWithError("meshes/round_brilliant.obj not found");
        return;
    }
    TraceSettings settings;
    settings.photons = 200'000;
    settings.light.model = LightModelKind::Hemisphere;
    std::vector<double> seconds[2];  // full, culled: per 1e6 photons
    for (auto _ : state) {
        for (bool culled : {false, true}) {
            ConvexIntersector::setCulling(culled);
            const Scene scene(*stone, settings);
            const TraceBase base(scene, settings);
            const double start = threadCpuSeconds();
            FacetStats stats(stone->facets.size());
            traceBlocks(base, 0, blockCount(settings.photons), 1, stats);
            benchmark::DoNotOptimize(stats.exited);
            seconds[culled].push_back((threadCpuSeconds() - start) / double(settings.photons) * 1e6);
        }
    }
    ConvexIntersector::setCulling(true);
    state.SetLabel(stone->name);
    state.counters["facets"] = double(stone->facets.size());
    state.counters["full_s_per_M"] = bench::median(seconds[0]);
    state.counters["culled_s_per_M"] = bench::median(seconds[1]);
    state.counters["culled_speedup"] = bench::median(seconds[0]) / bench::median(seconds[1]);
}
BENCHMARK(BM_CulledVsFullSearch)
    ->DenseRange(0, 3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(9);

// Absorption (issue 29) against the clear stone: the shipped brilliant in diamond on one thread, hemisphere
// light with dispersion (photons started one at a time) and one collimated beam without it (started a packet
// at a time), each timed alternately with the same stone absorbing a spectrum (target: at least 0.7x the
// clear stone's speed on every SIMD target, --simd=...).
void BM_AbsorbingVsPlain(benchmark::State& state) {
    const Stone* stone = shippedBrilliantOrSkip(state);
    if (!stone) return;
    struct Run {
        const char* name;
        LightModelKind light;
        bool absorbing;
        std::vector<double> seconds;
    };
    std::vector<Run> runs{{"hemisphere_clear", LightModelKind::Hemisphere, false, {}},
                          {"hemisphere_absorbing", LightModelKind::Hemisphere, true, {}},
                          {"beam_clear", LightModelKind::Collimated, false, {}},
                          {"beam_absorbing", LightModelKind::Collimated, true, {}}};
    for (auto _ : state) {
        for (Run& run : runs) {
            TraceSettings settings;
            settings.photons = 400'000;
            settings.light.model = run.light;
            settings.dispersion = run.light == LightModelKind::Hemisphere;
            // About a third of the light that enters a 6.5 mm stone is absorbed.
            if (run.absorbing)
                settings.absorption = AbsorptionSpectrum{{400, 550, 700}, {0.06, 0.02, 0.04}, {}};
            const Scene scene(*stone, settings);
            const TraceBase base(scene, settings);
            const auto start = std::chrono::steady_clock::now();
            FacetStats stats(stone->facets.size());
            traceBlocks(base, 0, blockCount(settings.photons), 1, stats);
            benchmark::DoNotOptimize(stats.exited);
            run.seconds.push_back(bench::seconds(start) / double(settings.photons) * 1e6);  // per 1e6 photons
            if (run.absorbing)
                state.counters[std::string(run.name) + "_absorbed_share"] =
                    double(stats.absorbed) / double(stats.entered);
        }
    }
    for (const Run& run : runs)
        state.counters[std::string(run.name) + "_s_per_M"] = bench::median(run.seconds);
    // Speed of the absorbing trace as a share of the clear one's (target >= 0.7).
    state.counters["hemisphere_speed_ratio"] =
        bench::median(runs[0].seconds) / bench::median(runs[1].seconds);
    state.counters["beam_speed_ratio"] = bench::median(runs[2].seconds) / bench::median(runs[3].seconds);
}
BENCHMARK(BM_AbsorbingVsPlain)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(5);

}  // namespace

int main(int argc, char** argv) {
    std::vector<char*> args;
    for (int i = 0; i < argc; ++i) {
        const std::string_view arg = argv[i];
        if (arg == "--simd=list") {
            for (const std::string& target : simdTargets()) std::printf("%s\n", target.c_str());
            return 0;
        }
        if (arg.starts_with("--simd=")) {
            limitSimdTarget(arg.substr(7));
        } else {
            args.push_back(argv[i]);
        }
    }
    int count = int(args.size());
    benchmark::Initialize(&count, args.data());
    if (benchmark::ReportUnrecognizedArguments(count, args.data())) return 1;
    benchmark::AddCustomContext("simd", simdTarget());
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
    return 0;
}
