// The photon map's gather and tree experiments, side by side in one run (tables for docs/performance.md):
//  1. gather methods on one 4 M photon map: radius doubling from 0.001 (the earlier study), PhotonMap's
//     gather with the cached radius (a range search) and without (a heap kNN, then a walk that orders the
//     answer), and nanoflann's kNN;
//  2. trees as photons grow: the balanced heap tree against a midpoint-split tree (the earlier study's
//     alternative) and nanoflann: build time and gather time.
// Photons are caustic-like: Gaussian spots and a ring on a floor over a uniform background. Queries walk a
// grid over the floor in raster order, like a camera's primary hits, and again in random order.
//
// Usage: photon_map_bench [--photons N] [--sizes N,N,...] [--queries-side S] [--k K] [--reps R] [--focus 1]
//                         [--irradiance FILE]
// --focus 1: only PhotonMap's tree build (1 and 2 threads) and cached-radius gather (1 and 2 threads), with
// hashes of the tree and of every gather's answer, so that two builds of the library can be compared for
// speed and for identical results in one script (bench/photon_map_ab.py); it also checks, untimed, that an
// estimate at every query has the same bits on 1 and 2 threads and in both orders.
// --irradiance FILE (with --focus 1): writes that estimate at every raster-order query, one thread, as
// doubles, to compare two builds' estimates (bench/compare_irradiance.py), and to FILE.sets their sets of k
// nearest.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <functional>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include <nanoflann.hpp>

#include "photonmap/photon_map.h"
#include "util/parallel.h"

namespace facetlight {
namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// A floor 4 x 4 units (a stone of girdle diameter about 1 in the middle).
std::vector<Photon> causticPhotons(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0, 1);
    std::normal_distribution<double> g(0, 1);
    struct Spot {
        double x, y, sigma;
    };
    std::vector<Spot> spots;
    for (int i = 0; i < 24; ++i)
        spots.push_back({3 * u(rng) - 1.5, 3 * u(rng) - 1.5, 0.005 + 0.1 * u(rng) * u(rng)});
    std::vector<Photon> photons;
    photons.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const double pick = u(rng);
        double x, y;
        if (pick < 0.3) {  // background
            x = 4 * u(rng) - 2;
            y = 4 * u(rng) - 2;
        } else if (pick < 0.45) {  // a caustic ring
            const double phi = 2 * kPi * u(rng), r = 0.8 + 0.01 * g(rng);
            x = r * std::cos(phi);
            y = r * std::sin(phi);
        } else {
            const Spot& s = spots[size_t(u(rng) * spots.size())];
            x = s.x + s.sigma * g(rng);
            y = s.y + s.sigma * g(rng);
        }
        const Vec3 travel{0.5 * g(rng), 0.5 * g(rng), -1};
        photons.push_back(Photon::make({x, y, 0}, 1e-6f, travel, 400 + 300 * u(rng)));
    }
    return photons;
}

std::vector<Vec3> rasterQueries(int side) {
    std::vector<Vec3> q;
    for (int j = 0; j < side; ++j)
        for (int i = 0; i < side; ++i)
            q.push_back({-1.8 + 3.6 * (i + 0.5) / side, -1.8 + 3.6 * (j + 0.5) / side, 0});
    return q;
}

struct Work {
    double nodes = 0;     // tree nodes visited per query
    double photons = 0;   // photons distance-tested per query
    double checksum = 0;  // sum of the k-th squared radii: equal for exact methods
};

// (a) The earlier study's gather: a range search of radius r, doubled from 0.001 until it holds k photons,
// then the k nearest of those. Walks the same heap tree.
class DoublingGather {
  public:
    DoublingGather(const PhotonMap& map, size_t k) : map_(map), k_(k) { found_.reserve(1 << 16); }

    float operator()(const Vec3& p, Work& work) {
        const float q[3] = {float(p.x), float(p.y), float(p.z)};
        for (float r = 0.001f;; r *= 2) {
            rangeSearch(q, r * r, work);
            if (found_.size() >= k_ || found_.size() == map_.size()) break;
        }
        const size_t k = std::min(k_, found_.size());
        std::nth_element(found_.begin(), found_.begin() + (k - 1), found_.end());
        return found_[k - 1].distance2;
    }

  private:
    void rangeSearch(const float q[3], float r2, Work& work) {
        found_.clear();
        const auto photons = map_.photons();
        const uint32_t n = uint32_t(photons.size());
        uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const uint32_t node = stack[--top];
            const Photon& ph = photons[node];
            work.nodes += 1;
            work.photons += 1;
            const float dx = q[0] - ph.position[0], dy = q[1] - ph.position[1], dz = q[2] - ph.position[2];
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < r2) found_.push_back({d2, node});
            const uint32_t left = 2 * node + 1;
            if (left >= n) continue;
            const float d = q[ph.axis()] - ph.position[ph.axis()];
            if (d < 0 || d * d < r2) stack[top++] = left;
            if (left + 1 < n && (d >= 0 || d * d < r2)) stack[top++] = left + 1;
        }
    }

    const PhotonMap& map_;
    size_t k_;
    std::vector<Neighbor> found_;
};

// The earlier study's other tree: split the longest axis of a node's box at its midpoint while the node
// holds more than kLeafSize photons. Nodes in depth-first order, photons permuted into leaf ranges.
class MidpointTree {
  public:
    static constexpr uint32_t kLeafSize = 8;

    explicit MidpointTree(std::vector<Photon> photons) : photons_(std::move(photons)) {
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (const Photon& p : photons_)
            for (int a = 0; a < 3; ++a) {
                lo[a] = std::min(lo[a], p.position[a]);
                hi[a] = std::max(hi[a], p.position[a]);
            }
        nodes_.reserve(2 * photons_.size() / kLeafSize + 16);
        build(0, uint32_t(photons_.size()), lo, hi, 0);
    }

    size_t nodeCount() const { return nodes_.size(); }

    float knn(const Vec3& p, Neighbor* heap, uint32_t k, Work& work) const {
        const float q[3] = {float(p.x), float(p.y), float(p.z)};
        float r2 = INFINITY;
        uint32_t found = 0;
        struct Pending {
            uint32_t node;
            float plane2;
        } stack[128];
        int top = 0;
        stack[top++] = {0, 0};
        while (top > 0) {
            const Pending e = stack[--top];
            if (e.plane2 >= r2) continue;
            uint32_t node = e.node;
            while (!nodes_[node].leaf) {
                work.nodes += 1;
                const Node& nd = nodes_[node];
                const float d = q[nd.axis] - nd.split;
                const uint32_t nearChild = d < 0 ? node + 1 : nd.right,
                               farChild = d < 0 ? nd.right : node + 1;
                if (d * d < r2) stack[top++] = {farChild, d * d};
                node = nearChild;
            }
            work.nodes += 1;
            const Node& leaf = nodes_[node];
            for (uint32_t i = leaf.begin; i < leaf.end; ++i) {
                const Photon& ph = photons_[i];
                work.photons += 1;
                const float dx = q[0] - ph.position[0], dy = q[1] - ph.position[1],
                            dz = q[2] - ph.position[2];
                const float d2 = dx * dx + dy * dy + dz * dz;
                if (d2 >= r2) continue;
                if (found < k) {
                    heap[found++] = {d2, i};
                    std::push_heap(heap, heap + found);
                    if (found == k) r2 = heap[0].distance2;
                } else {
                    std::pop_heap(heap, heap + k);
                    heap[k - 1] = {d2, i};
                    std::push_heap(heap, heap + k);
                    r2 = heap[0].distance2;
                }
            }
        }
        return found ? heap[0].distance2 : 0;
    }

  private:
    struct Node {
        bool leaf;
        uint8_t axis;
        float split;
        uint32_t right;       // inner: the right child (the left one follows its parent)
        uint32_t begin, end;  // leaf: its photons
    };

    void build(uint32_t begin, uint32_t end, const float lo[3], const float hi[3], int depth) {
        const uint32_t index = uint32_t(nodes_.size());
        nodes_.push_back({});
        const float ext[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
        const int axis = ext[0] >= ext[1] ? (ext[0] >= ext[2] ? 0 : 2) : (ext[1] >= ext[2] ? 1 : 2);
        // Depth bounds the recursion where photons coincide.
        if (end - begin <= kLeafSize || depth >= 60) {
            nodes_[index] = {true, 0, 0, 0, begin, end};
            return;
        }
        const float split = 0.5f * (lo[axis] + hi[axis]);
        Photon* mid = std::partition(photons_.data() + begin, photons_.data() + end,
                                     [&](const Photon& p) { return p.position[axis] < split; });
        const uint32_t m = uint32_t(mid - photons_.data());
        float leftHi[3] = {hi[0], hi[1], hi[2]}, rightLo[3] = {lo[0], lo[1], lo[2]};
        leftHi[axis] = rightLo[axis] = split;
        build(begin, m, lo, leftHi, depth + 1);
        const uint32_t right = uint32_t(nodes_.size());
        build(m, end, rightLo, hi, depth + 1);
        nodes_[index] = {false, uint8_t(axis), split, right, 0, 0};
    }

    std::vector<Photon> photons_;
    std::vector<Node> nodes_;
};

struct NanoflannCloud {
    const Photon* photons;
    size_t n;
    size_t kdtree_get_point_count() const { return n; }
    float kdtree_get_pt(size_t i, size_t d) const { return photons[i].position[d]; }
    template <class Box>
    bool kdtree_get_bbox(Box&) const {
        return false;
    }
};
using NanoflannTree = nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<float, NanoflannCloud>,
                                                          NanoflannCloud, 3, uint32_t>;

float nanoflannKnn(const NanoflannTree& tree, const Vec3& p, uint32_t* index, float* dist2, size_t k) {
    const float q[3] = {float(p.x), float(p.y), float(p.z)};
    nanoflann::KNNResultSet<float, uint32_t> result(k);
    result.init(index, dist2);
    tree.findNeighbors(result, q, nanoflann::SearchParams());
    return result.worstDist();
}

// Runs each method over the queries `reps` times, interleaved so that all see the same machine state;
// returns the median queries per second of each.
struct Method {
    std::string name;
    std::function<float(const Vec3&, Work&)> gather;
    std::vector<double> rates;
    Work work;
};

void runSideBySide(std::vector<Method>& methods, const std::vector<Vec3>& queries, int reps) {
    for (int r = 0; r < reps; ++r) {
        for (Method& m : methods) {
            Work work;
            const auto t0 = Clock::now();
            for (const Vec3& q : queries) work.checksum += m.gather(q, work);
            const auto t1 = Clock::now();
            m.rates.push_back(queries.size() / seconds(t0, t1));
            m.work = work;
        }
    }
}

// FNV-1a, 64 bits.
struct Hash {
    uint64_t h = 1469598103934665603ull;
    void add(const void* data, size_t bytes) {
        const auto* b = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < bytes; ++i) h = (h ^ b[i]) * 1099511628211ull;
    }
};

// Wall and process CPU seconds of one run: on a shared machine the CPU seconds count the work alone, the
// wall seconds the work and the waits for a core.
struct Timer {
    Clock::time_point wall = Clock::now();
    double cpu = cpuNow();
    static double cpuNow() {
        timespec t;
        clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
        return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
    }
    void stop(std::vector<double>& wallSeconds, std::vector<double>& cpuSeconds) const {
        wallSeconds.push_back(seconds(wall, Clock::now()));
        cpuSeconds.push_back(cpuNow() - cpu);
    }
};

// The tree build and the cached-radius gather alone, interleaved repetitions, with hashes of the results.
void runFocus(size_t photonCount, int side, size_t k, int reps, const std::string& dumpPath) {
    const std::vector<Photon> photons = causticPhotons(photonCount, 1);
    std::vector<double> wall[2], cpu[2];
    for (int r = 0; r < reps; ++r)
        for (int threads : {1, 2}) {
            std::vector<Photon> copy = photons;
            const Timer t;
            const PhotonMap map(std::move(copy), threads);
            t.stop(wall[threads - 1], cpu[threads - 1]);
        }
    const PhotonMap map(photons, 2);
    Hash tree;
    tree.add(map.photons().data(), map.size() * sizeof(Photon));
    std::printf(
        "tree, %zu photons, median of %d: 1 thread %.0f ms (CPU %.0f ms), 2 threads %.0f ms (CPU %.0f "
        "ms); tree hash %016llx\n",
        photonCount, reps, median(wall[0]) * 1e3, median(cpu[0]) * 1e3, median(wall[1]) * 1e3,
        median(cpu[1]) * 1e3, (unsigned long long)tree.h);

    const std::vector<Vec3> raster = rasterQueries(side);
    const std::vector<Vec3> shuffled = [&] {
        std::vector<Vec3> s = raster;
        std::shuffle(s.begin(), s.end(), std::mt19937(5));
        return s;
    }();
    // Untimed: the estimate at every query (by its place in `raster`), one thread in each order and two
    // threads in blocks, each thread with its own state, as the renderer's workers gather.
    std::vector<size_t> place(raster.size());
    {
        std::vector<size_t> perm(raster.size());
        std::iota(perm.begin(), perm.end(), size_t(0));
        std::shuffle(perm.begin(), perm.end(), std::mt19937(5));  // the same shuffle as `shuffled`
        place = perm;
        for (size_t i = 0; i < place.size(); ++i)
            if (!(shuffled[i] == raster[place[i]])) std::abort();
    }
    // An estimate like the renderer's: its cone filter, and photons weighed by wavelength, so that the terms
    // differ and the order of the sum shows in the last bits.
    GatherSettings cone;
    cone.coneK = 1.1f;
    auto estimate = [&](const Vec3& q, std::vector<Neighbor>& buffer, GatherState& state) {
        return map.estimate<double>(q, buffer, state, cone, [](const Photon& ph) {
            return ph.travel().z < 0 ? double(ph.power) * ph.wavelength() / 550 : 0.0;
        });
    };
    auto irradianceOneThread = [&](const std::vector<Vec3>& order, bool shuffledOrder) {
        std::vector<double> e(raster.size());
        std::vector<Neighbor> buffer(k);
        GatherState state;
        for (size_t i = 0; i < order.size(); ++i)
            e[shuffledOrder ? place[i] : i] = estimate(order[i], buffer, state);
        return e;
    };
    const std::vector<double> eRaster = irradianceOneThread(raster, false);
    const std::vector<double> eRandom = irradianceOneThread(shuffled, true);
    std::vector<double> eTwo(raster.size());
    struct EstimateWorker {
        std::vector<Neighbor> buffer;
        GatherState state;
    };
    parallelForBlocks(BlockLoop{0, shuffled.size(), 4096, 2}, nullptr,
                      EstimateWorker{std::vector<Neighbor>(k), {}},
                      [&](EstimateWorker& w, uint64_t first, uint64_t last) {
                          for (uint64_t i = first; i < last; ++i)
                              eTwo[place[i]] = estimate(shuffled[i], w.buffer, w.state);
                          return uint64_t(0);
                      });
    Hash irradianceHash;
    irradianceHash.add(eRaster.data(), eRaster.size() * sizeof(double));
    auto same = [&](const std::vector<double>& e) {
        return std::memcmp(e.data(), eRaster.data(), e.size() * sizeof(double)) == 0 ? "yes" : "no";
    };
    std::printf(
        "estimates at the raster queries: hash %016llx; same bits in random order %s, on 2 threads %s\n",
        (unsigned long long)irradianceHash.h, same(eRandom), same(eTwo));
    if (!dumpPath.empty()) {
        std::FILE* f = std::fopen(dumpPath.c_str(), "wb");
        if (!f || std::fwrite(eRaster.data(), sizeof(double), eRaster.size(), f) != eRaster.size()) {
            std::fprintf(stderr, "cannot write %s\n", dumpPath.c_str());
            std::exit(1);
        }
        std::fclose(f);
        // FILE.sets: each raster-order query's k-th squared distance (a float) and its photons' indices in
        // increasing order (k uint32s), from a fresh state: the sets of two builds compare photon by photon.
        f = std::fopen((dumpPath + ".sets").c_str(), "wb");
        std::vector<Neighbor> buffer(k);
        std::vector<uint32_t> set;
        GatherState state;
        for (const Vec3& q : raster) {
            const GatherResult g = map.gather(q, buffer, state);
            set.clear();
            for (const Neighbor& n : g.neighbors) set.push_back(n.index);
            std::sort(set.begin(), set.end());
            set.resize(k, UINT32_MAX);
            if (!f || std::fwrite(&g.radius2, sizeof(float), 1, f) != 1 ||
                std::fwrite(set.data(), sizeof(uint32_t), k, f) != k) {
                std::fprintf(stderr, "cannot write %s.sets\n", dumpPath.c_str());
                std::exit(1);
            }
        }
        std::fclose(f);
    }
    for (const auto* order : {&raster, &shuffled}) {
        for (auto* v : {&wall[0], &wall[1], &cpu[0], &cpu[1]}) v->clear();
        Hash answers;
        for (int r = 0; r < reps; ++r) {
            {
                std::vector<Neighbor> buffer(k);
                GatherState state;
                Hash h;
                const Timer t;
                for (const Vec3& q : *order) {
                    const GatherResult g = map.gather(q, buffer, state);
                    h.add(g.neighbors.data(), g.neighbors.size_bytes());
                    h.add(&g.radius2, sizeof g.radius2);
                }
                t.stop(wall[0], cpu[0]);
                answers = h;
            }
            // Two threads, each with its own state, on blocks of consecutive queries.
            struct Worker {
                std::vector<Neighbor> buffer;
                GatherState state;
            };
            const Timer t;
            parallelForBlocks(BlockLoop{0, order->size(), 4096, 2}, nullptr,
                              Worker{std::vector<Neighbor>(k), {}},
                              [&](Worker& w, uint64_t first, uint64_t last) {
                                  for (uint64_t i = first; i < last; ++i)
                                      map.gather((*order)[i], w.buffer, w.state);
                                  return uint64_t(0);
                              });
            t.stop(wall[1], cpu[1]);
        }
        const double q = double(order->size()) / 1e3;
        std::printf(
            "gather, k = %zu, %zu queries in %s order, median of %d: 1 thread %.1f k/s (%.1f k per CPU s), "
            "2 threads %.1f k/s (%.1f k per CPU s); answers hash (1 thread) %016llx\n",
            k, order->size(), order == &raster ? "raster" : "random", reps, q / median(wall[0]),
            q / median(cpu[0]), q / median(wall[1]), q / median(cpu[1]), (unsigned long long)answers.h);
    }
}

std::vector<size_t> parseSizes(const char* s) {
    std::vector<size_t> sizes;
    for (const char* p = s; *p;) {
        char* end;
        sizes.push_back(std::strtoull(p, &end, 10));
        p = *end == ',' ? end + 1 : end;
    }
    return sizes;
}

int run(int argc, char** argv) {
    size_t photonCount = 4'000'000;
    std::vector<size_t> sizes = {250'000, 1'000'000, 4'000'000};
    int side = 256;
    size_t k = 100;
    int reps = 5;
    bool focus = false;
    std::string dumpPath;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--photons")
            photonCount = std::strtoull(argv[i + 1], nullptr, 10);
        else if (flag == "--sizes")
            sizes = parseSizes(argv[i + 1]);
        else if (flag == "--queries-side")
            side = std::atoi(argv[i + 1]);
        else if (flag == "--k")
            k = std::strtoull(argv[i + 1], nullptr, 10);
        else if (flag == "--reps")
            reps = std::atoi(argv[i + 1]);
        else if (flag == "--focus")
            focus = std::atoi(argv[i + 1]) != 0;
        else if (flag == "--irradiance")
            dumpPath = argv[i + 1];
        else {
            std::fprintf(stderr, "unknown flag %s\n", argv[i]);
            return 2;
        }
    }
    if (focus) {
        runFocus(photonCount, side, k, reps, dumpPath);
        return 0;
    }
    const std::vector<Vec3> raster = rasterQueries(side);
    const std::vector<Vec3> shuffled = [&] {
        std::vector<Vec3> s = raster;
        std::shuffle(s.begin(), s.end(), std::mt19937(5));
        return s;
    }();
    std::vector<Neighbor> buffer(k);
    std::vector<uint32_t> nfIndex(k);
    std::vector<float> nfDist(k);

    // 1. Gather methods on one map.
    {
        const std::vector<Photon> photons = causticPhotons(photonCount, 1);
        const PhotonMap map(photons, 2);
        const NanoflannCloud cloud{photons.data(), photons.size()};
        const NanoflannTree nano(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
        DoublingGather doubling(map, k);
        GatherState cachedState, plainState;
        GatherSettings cached, plain;
        plain.cachedRadius = false;
        auto heapGather = [&](GatherState& state, const GatherSettings& s) {
            return [&](const Vec3& q, Work& work) {
                const uint64_t before = state.nodesVisited;
                const float r2 = map.gather(q, buffer, state, s).radius2;
                work.nodes += double(state.nodesVisited - before);
                work.photons += double(state.nodesVisited - before);
                return r2;
            };
        };
        auto nanoGather = [&](const Vec3& q, Work&) {
            return nanoflannKnn(nano, q, nfIndex.data(), nfDist.data(), k);
        };
        for (const auto* order : {&raster, &shuffled}) {
            cachedState = {};
            std::vector<Method> methods = {
                {"(a) radius doubling from 0.001", std::ref(doubling), {}, {}},
                {"(b) range search, cached radius 1.15x", heapGather(cachedState, cached), {}, {}},
                {"(c) heap kNN + ordering walk, no bound", heapGather(plainState, plain), {}, {}},
                {"(d) nanoflann kNN (leaf 10)", nanoGather, {}, {}},
            };
            runSideBySide(methods, *order, reps);
            std::printf("\n### Gather, k = %zu, %zu photons, %zu queries in %s order, median of %d runs\n\n",
                        k, photonCount, order->size(), order == &raster ? "raster" : "random", reps);
            std::printf("| method | queries/s | vs (a) | nodes visited/query | photons tested/query |\n");
            std::printf("|---|---:|---:|---:|---:|\n");
            const double base = median(methods[0].rates);
            for (const Method& m : methods) {
                const double q = double(order->size());
                const bool counted = m.work.nodes > 0;
                std::printf("| %s | %.0f k | %.2fx | %s | %s |\n", m.name.c_str(), median(m.rates) / 1e3,
                            median(m.rates) / base,
                            counted ? std::to_string(int(m.work.nodes / q)).c_str() : "n/a",
                            counted ? std::to_string(int(m.work.photons / q)).c_str() : "n/a");
            }
            std::printf("\nk-th radius checksums (exact methods agree): ");
            for (const Method& m : methods) std::printf("%.6g ", m.work.checksum);
            std::printf(
                "\ncached radius: searched again %.1f times a hundred queries\n",
                100.0 * double(cachedState.retries) / double(std::max<uint64_t>(cachedState.queries, 1)));
        }
    }

    // 2. Trees as photons grow.
    std::printf(
        "\n### Trees, k = %zu, %zu raster-order queries, median of %d runs (build: 1 thread unless "
        "noted)\n\n",
        k, raster.size(), reps);
    std::printf(
        "| photons | heap build | heap build, 2 threads | midpoint build (leaf %u) | nanoflann build | "
        "heap gather (b) | heap gather (c) | midpoint gather | nanoflann gather | heap photons tested (c) | "
        "midpoint photons tested |\n",
        MidpointTree::kLeafSize);
    std::printf("|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (size_t n : sizes) {
        const std::vector<Photon> photons = causticPhotons(n, 2);
        std::vector<double> heapBuild, heapBuild2, midBuild, nanoBuild;
        for (int r = 0; r < reps; ++r) {
            for (int threads : {1, 2}) {
                std::vector<Photon> copy = photons;
                const auto t0 = Clock::now();
                const PhotonMap map(std::move(copy), threads);
                (threads == 1 ? heapBuild : heapBuild2).push_back(seconds(t0, Clock::now()));
            }
            std::vector<Photon> copy = photons;
            auto t0 = Clock::now();
            const MidpointTree mid(std::move(copy));
            midBuild.push_back(seconds(t0, Clock::now()));
            const NanoflannCloud cloud{photons.data(), photons.size()};
            t0 = Clock::now();
            const NanoflannTree nano(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
            nanoBuild.push_back(seconds(t0, Clock::now()));
        }
        const PhotonMap map(photons, 2);
        const MidpointTree mid(photons);
        const NanoflannCloud cloud{photons.data(), photons.size()};
        const NanoflannTree nano(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
        GatherState cachedState, plainState;
        GatherSettings cached, plain;
        plain.cachedRadius = false;
        std::vector<Method> methods = {
            {"heap (b)",
             [&](const Vec3& q, Work& w) {
                 const uint64_t before = cachedState.nodesVisited;
                 const float r2 = map.gather(q, buffer, cachedState, cached).radius2;
                 w.photons += double(cachedState.nodesVisited - before);
                 return r2;
             },
             {},
             {}},
            {"heap (c)",
             [&](const Vec3& q, Work& w) {
                 const uint64_t before = plainState.nodesVisited;
                 const float r2 = map.gather(q, buffer, plainState, plain).radius2;
                 w.photons += double(plainState.nodesVisited - before);
                 return r2;
             },
             {},
             {}},
            {"midpoint",
             [&](const Vec3& q, Work& w) { return mid.knn(q, buffer.data(), uint32_t(k), w); },
             {},
             {}},
            {"nanoflann",
             [&](const Vec3& q, Work&) { return nanoflannKnn(nano, q, nfIndex.data(), nfDist.data(), k); },
             {},
             {}},
        };
        runSideBySide(methods, raster, reps);
        const double q = double(raster.size());
        std::printf(
            "| %zu | %.0f ms | %.0f ms | %.0f ms | %.0f ms | %.0f k/s | %.0f k/s | %.0f k/s | %.0f k/s | "
            "%.0f | %.0f |\n",
            n, median(heapBuild) * 1e3, median(heapBuild2) * 1e3, median(midBuild) * 1e3,
            median(nanoBuild) * 1e3, median(methods[0].rates) / 1e3, median(methods[1].rates) / 1e3,
            median(methods[2].rates) / 1e3, median(methods[3].rates) / 1e3, methods[1].work.photons / q,
            methods[2].work.photons / q);
    }
    return 0;
}

}  // namespace
}  // namespace facetlight

int main(int argc, char** argv) {
    return facetlight::run(argc, argv);
}
