#include "photonmap/photon_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <random>

#include "util/error.h"

namespace facetlight {
namespace {

const Vec3 kDown{0, 0, -1};

std::vector<Photon> uniformCube(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<Photon> photons;
    for (size_t i = 0; i < n; ++i) photons.push_back(Photon::make({u(rng), u(rng), u(rng)}, 1, kDown));
    return photons;
}

// Caustic-like: tight Gaussian clusters on a floor over a thin uniform background, with exact duplicates.
std::vector<Photon> clustered(size_t n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    std::normal_distribution<double> g(0, 1);
    std::vector<Vec3> centres;
    for (int c = 0; c < 6; ++c) centres.push_back({u(rng), u(rng), 0});
    std::vector<Photon> photons;
    while (photons.size() < n) {
        const double pick = 0.5 * (u(rng) + 1);
        Vec3 p;
        if (pick < 0.2) {
            p = {u(rng), u(rng), 0};
        } else {
            const Vec3& c = centres[size_t(pick * 100) % centres.size()];
            p = c + Vec3{g(rng), g(rng), 0} * 0.02;
        }
        photons.push_back(Photon::make(p, 1, kDown));
        if (pick > 0.95 && photons.size() < n) photons.push_back(photons.back());  // duplicate
    }
    return photons;
}

double distance2(const Photon& p, const Vec3& q) {
    const Vec3 d = p.pos() - q;
    return dot(d, d);
}

// The squared distance as the gather computes it: in float, one rounding an operation.
float distance2f(const Photon& p, const Vec3& q) {
    const float dx = float(q.x) - p.position[0], dy = float(q.y) - p.position[1],
                dz = float(q.z) - p.position[2];
    return dx * dx + dy * dy + dz * dz;
}

// The gather must return k distinct photons none farther than the k-th nearest by brute force: exactly the
// first k by (squared distance in float, index), ties going to the lower index.
void expectNearest(const PhotonMap& map, const Vec3& q, size_t k, GatherState& state,
                   const GatherSettings& settings) {
    std::vector<double> all;
    for (const Photon& p : map.photons()) all.push_back(distance2(p, q));
    std::sort(all.begin(), all.end());
    const double max2 = double(settings.maxRadius) * settings.maxRadius;
    const size_t within = size_t(std::lower_bound(all.begin(), all.end(), max2) - all.begin());
    const size_t expected = std::min(k, within);

    std::vector<Neighbor> buffer(k);
    const GatherResult g = map.gather(q, buffer, state, settings);
    ASSERT_EQ(g.neighbors.size(), expected) << "query " << q.x << " " << q.y << " " << q.z;
    if (expected == 0) return;
    const double kth = all[expected - 1];
    std::vector<uint32_t> seen;
    for (const Neighbor& n : g.neighbors) {
        ASSERT_LT(n.index, map.size());
        seen.push_back(n.index);
        EXPECT_LE(distance2(map.photons()[n.index], q), kth * (1 + 1e-5) + 1e-12);
        EXPECT_NEAR(n.distance2, distance2(map.photons()[n.index], q), 1e-5 * (kth + 1e-6));
    }
    std::sort(seen.begin(), seen.end());
    EXPECT_EQ(std::adjacent_find(seen.begin(), seen.end()), seen.end()) << "a photon returned twice";
    std::vector<std::pair<float, uint32_t>> keys;
    for (uint32_t i = 0; i < map.size(); ++i) {
        const float d2 = distance2f(map.photons()[i], q);
        if (d2 < float(settings.maxRadius) * settings.maxRadius) keys.push_back({d2, i});
    }
    std::sort(keys.begin(), keys.end());
    std::vector<uint32_t> first;
    for (size_t i = 0; i < std::min(k, keys.size()); ++i) first.push_back(keys[i].second);
    std::sort(first.begin(), first.end());
    EXPECT_EQ(seen, first) << "not the k first by distance, then index";
    if (expected == k) {
        EXPECT_NEAR(g.radius2, kth, 1e-5 * kth + 1e-12);
    }
}

TEST(Photon, PacksDirectionWavelengthAndAxis) {
    std::mt19937 rng(7);
    std::normal_distribution<double> g;
    for (int i = 0; i < 2000; ++i) {
        const Vec3 d = normalize({g(rng), g(rng), g(rng)});
        Photon p = Photon::make({1, 2, 3}, 0.5f, d * 3.0, 380 + i * 0.2);
        p.setAxis(i % 3);
        EXPECT_GT(dot(p.travel(), d), std::cos(radians(1.0)));
        EXPECT_NEAR(p.wavelength(), 380 + i * 0.2, 0.051);
        EXPECT_EQ(p.axis(), i % 3);
    }
    for (const Vec3& d : {Vec3{0, 0, 1}, Vec3{0, 0, -1}, Vec3{1, 0, 0}, Vec3{0, -1, 0}})
        EXPECT_GT(dot(Photon::make({}, 1, d).travel(), d), std::cos(radians(1.0)));
}

// Every node's split plane separates its left and right subtrees, and the tree is a permutation of the input.
void expectHeapOrderedKdTree(const std::vector<Photon>& input) {
    const PhotonMap map(input);
    ASSERT_EQ(map.size(), input.size());
    const auto photons = map.photons();
    for (size_t i = 0; i < photons.size(); ++i) {
        const int axis = photons[i].axis();
        ASSERT_LT(axis, 3);
        const float split = photons[i].position[axis];
        for (size_t child = 2 * i + 1, side = 0; side < 2; ++child, ++side) {
            std::vector<size_t> pending{child};
            while (!pending.empty()) {
                const size_t j = pending.back();
                pending.pop_back();
                if (j >= photons.size()) continue;
                const float x = photons[j].position[axis];
                ASSERT_TRUE(side == 0 ? x <= split : x >= split) << "node " << i << " child " << j;
                pending.push_back(2 * j + 1);
                pending.push_back(2 * j + 2);
            }
        }
    }
    // The tree is a permutation of the input.
    auto key = [](const Photon& p) { return std::tuple(p.position[0], p.position[1], p.position[2]); };
    std::vector<std::tuple<float, float, float>> a, b;
    for (const Photon& p : input) a.push_back(key(p));
    for (const Photon& p : photons) b.push_back(key(p));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
}

TEST(PhotonMap, IsAHeapOrderedKdTreeOfTheInput) {
    expectHeapOrderedKdTree(clustered(5000, 1));
}

// Photons on a coarse grid share coordinates by the hundred: the median selection must still progress.
TEST(PhotonMap, IsAHeapOrderedKdTreeWhenCoordinatesRepeat) {
    std::vector<Photon> grid;
    for (int i = 0; i < 4000; ++i)
        grid.push_back(Photon::make({double(i % 5), double(i % 7 / 3), 0}, 1, kDown));
    expectHeapOrderedKdTree(grid);
    expectHeapOrderedKdTree(std::vector<Photon>(1000, grid[3]));
    const PhotonMap map(grid);
    GatherState state;
    for (size_t k : {1, 30, 700}) expectNearest(map, {1.2, 0.4, 0}, k, state, {});
}

TEST(PhotonMap, BuildIsDeterministicWhateverTheThreadCount) {
    const std::vector<Photon> input = clustered(30000, 2);
    const PhotonMap one(input, 1), two(input, 2), five(input, 5);
    ASSERT_EQ(one.size(), input.size());
    EXPECT_EQ(std::memcmp(one.photons().data(), two.photons().data(), input.size() * sizeof(Photon)), 0);
    EXPECT_EQ(std::memcmp(one.photons().data(), five.photons().data(), input.size() * sizeof(Photon)), 0);
}

// FNV-1a over bytes, to pin a tree and a run of gathers to the bit.
struct Fnv {
    uint64_t h = 1469598103934665603ull;
    template <class T>
    void add(const T* data, size_t count) {
        const auto* b = reinterpret_cast<const unsigned char*>(data);
        for (size_t i = 0; i < count * sizeof(T); ++i) h = (h ^ b[i]) * 1099511628211ull;
    }
};

// Photons from raw mt19937 words (the same on every standard library): clusters on a floor over a
// background, on a grid of 2^-12 so that coordinates tie by the thousand, with exact duplicates.
std::vector<Photon> tiedCaustic(size_t n) {
    std::mt19937 rng(21);
    auto unit = [&] { return double(rng() >> 20) / 4096; };  // [0, 1) in steps of 2^-12
    std::vector<Photon> photons;
    while (photons.size() < n) {
        const uint32_t pick = rng() % 8;
        Vec3 p{unit(), unit(), 0};
        if (pick >= 2) p = Vec3{0.1 * pick, 0.05 * pick, 0} + Vec3{unit(), unit(), unit()} * 0.03;
        photons.push_back(Photon::make(p, float(1 + pick), {1, 0.5, -1.0 - pick}, 400 + 30 * pick));
        if (pick == 7 && photons.size() < n) photons.push_back(photons.back());
    }
    return photons;
}

// The tree's bytes and every gather's answer (the photons, their order, the radius) and irradiance bits,
// pinned so that a faster tree or gather cannot move a render's bits unnoticed, ties and all; a change that
// means to move them changes these and says why. The tree's hash is main's since f963aad. The gather's moved
// once (issue 32, the gather by range search): the neighbours come in walk order (the last 4 levels'
// subtrees in index order) instead of the order a max-heap left them in, so the estimates' sums add the same
// photons in another order (their last bits move), and a tie at the k-th distance now goes to the lower index
// instead of the photon the walk met first (the same k-th distance, another photon). The sets of k nearest
// are checked photon by photon against brute force by the GathersExactly tests below.
TEST(PhotonMap, TreeAndGathersAreBitForBitThoseOfTheReference) {
    const std::vector<Photon> input = tiedCaustic(20000);
    for (int threads : {1, 2, 3}) {
        const PhotonMap map(input, threads);
        Fnv tree;
        tree.add(map.photons().data(), map.size());
        EXPECT_EQ(tree.h, 12820187859836620088ull) << threads << " threads";
    }
    const PhotonMap map(input, 2);
    std::mt19937 rng(22);
    Fnv answers;
    for (bool cached : {true, false}) {
        for (size_t k : {1, 16, 100}) {
            std::vector<Neighbor> buffer(k);
            GatherState state;
            GatherSettings settings;
            settings.cachedRadius = cached;
            for (int i = 0; i < 300; ++i) {
                // Raster-like runs of near queries, then jumps; a third on a photon (ties at distance 0).
                const Vec3 q = i % 3 == 0 ? input[rng() % input.size()].pos()
                                          : Vec3{(i % 30) / 40.0, (i / 30) / 12.0, 0.01 * (i % 5)};
                const GatherResult g = map.gather(q, buffer, state, settings);
                answers.add(g.neighbors.data(), g.neighbors.size());
                answers.add(&g.radius2, 1);
                const double e = map.irradiance(q, {0, 0.3, 1}, buffer, state, settings);
                answers.add(&e, 1);
            }
        }
    }
    EXPECT_EQ(answers.h, 758269181471337556ull);
}

// An answer depends on the query alone: not on the cached radius the thread's earlier gathers left (tiny,
// huge, none), nor on whether the radius is cached. So a render's bits do not depend on which thread gathered
// which pixel after which.
TEST(PhotonMap, GatherAnswersDependOnlyOnThePoint) {
    const std::vector<Photon> input = tiedCaustic(20000);
    const PhotonMap map(input, 1);
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> u(0, 1);
    for (size_t k : {1, 16, 100}) {
        std::vector<Neighbor> a(k), b(k);
        GatherState fresh;
        for (int i = 0; i < 300; ++i) {
            const Vec3 q =
                i % 3 == 0 ? input[rng() % input.size()].pos() : Vec3{u(rng), u(rng), 0.02 * u(rng)};
            // The first gather of a fresh state finds no cached radius; then one primed in a dense spot (a
            // small radius, searched again) or on the sparse background far away (a large one).
            GatherState primed;
            const Vec3 prime = i % 2 ? input[rng() % input.size()].pos() : Vec3{3, 3, 0};
            map.gather(prime, b, primed);
            GatherSettings plain;
            plain.cachedRadius = false;
            const GatherResult ga = map.gather(q, a, fresh);
            for (GatherState* s : {&primed, &fresh}) {
                for (bool cached : {true, false}) {
                    plain.cachedRadius = cached;
                    GatherState copy = *s;
                    const GatherResult gb = map.gather(q, b, copy, plain);
                    ASSERT_EQ(ga.neighbors.size(), gb.neighbors.size());
                    EXPECT_EQ(
                        std::memcmp(ga.neighbors.data(), gb.neighbors.data(), ga.neighbors.size_bytes()), 0)
                        << "k " << k << " query " << i;
                    EXPECT_EQ(ga.radius2, gb.radius2);
                    GatherState copyA = fresh, copyB = *s;
                    EXPECT_EQ(map.irradiance(q, {0, 0.3, 1}, a, copyA),
                              map.irradiance(q, {0, 0.3, 1}, b, copyB, plain));
                }
            }
        }
    }
}

TEST(PhotonMap, GathersExactlyTheKNearestOfRandomPhotons) {
    const PhotonMap map(uniformCube(4000, 3));
    std::mt19937 rng(4);
    std::uniform_real_distribution<double> u(-1.5, 1.5);  // inside and outside the cloud
    for (size_t k : {1, 7, 50, 300}) {
        for (bool cached : {false, true}) {
            GatherState state;
            GatherSettings settings;
            settings.cachedRadius = cached;
            for (int i = 0; i < 60; ++i) expectNearest(map, {u(rng), u(rng), u(rng)}, k, state, settings);
        }
    }
}

TEST(PhotonMap, GathersExactlyTheKNearestOfClusteredPhotonsWithDuplicates) {
    const std::vector<Photon> input = clustered(6000, 5);
    const PhotonMap map(input);
    std::mt19937 rng(6);
    std::uniform_int_distribution<size_t> pick(0, input.size() - 1);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    for (size_t k : {1, 10, 100, 400}) {
        GatherState state;
        const GatherSettings settings;  // cached radius on: queries jump between dense and sparse places
        for (int i = 0; i < 40; ++i) {
            expectNearest(map, input[pick(rng)].pos(), k, state,
                          settings);  // on a photon (and its duplicates)
            expectNearest(map, {u(rng), u(rng), 0.1 * u(rng)}, k, state, settings);
        }
        EXPECT_EQ(state.queries, 80u);
    }
}

TEST(PhotonMap, MaxRadiusLimitsTheGather) {
    const PhotonMap map(clustered(3000, 8));
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1.2, 1.2);
    GatherSettings settings;
    settings.maxRadius = 0.05f;
    GatherState state;
    for (int i = 0; i < 100; ++i) expectNearest(map, {u(rng), u(rng), 0}, 50, state, settings);
}

TEST(PhotonMap, HandlesTinyAndEmptyMaps) {
    const PhotonMap empty;
    std::vector<Neighbor> buffer(5);
    GatherState state;
    EXPECT_TRUE(empty.gather({0, 0, 0}, buffer, state).neighbors.empty());
    EXPECT_EQ(empty.irradiance({0, 0, 0}, {0, 0, 1}, buffer, state), 0.0);
    for (size_t n = 1; n <= 9; ++n) {
        const PhotonMap map(uniformCube(n, uint32_t(n)));
        for (size_t k : {size_t(1), n, n + 3}) expectNearest(map, {0.1, 0.2, 0.3}, k, state, {});
    }
}

TEST(PhotonMap, RejectsNonFinitePositions) {
    std::vector<Photon> photons = uniformCube(10, 1);
    photons[4].position[1] = NAN;
    EXPECT_THROW(PhotonMap{photons}, Error);
}

// N photons of total power P spread uniformly over the unit square: irradiance P / 1 everywhere inside.
TEST(PhotonMap, IrradianceOfAUniformlyLitFloorMatchesTheAnalyticValue) {
    const size_t n = 200000;
    const double power = 3.0;
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Photon> photons;
    for (size_t i = 0; i < n; ++i)
        photons.push_back(Photon::make({u(rng), u(rng), 0}, float(power / n), {0.3, -0.2, -1}, 550));
    // Photons arriving from below the floor light its other side and must not count.
    for (size_t i = 0; i < n / 10; ++i)
        photons.push_back(Photon::make({u(rng), u(rng), 0}, float(power / n), {0, 0, 1}, 550));
    const PhotonMap map(std::move(photons));

    for (size_t k : {50, 200, 800}) {
        for (float coneK : {0.0f, 1.1f}) {
            std::vector<Neighbor> buffer(k);
            GatherState state;
            GatherSettings settings;
            settings.coneK = coneK;
            // The disc holding the k nearest of a uniform density covers a Gamma(k, 1)-distributed number of
            // photons' worth of area (mean k, sd sqrt(k)), so the estimate is k / Gamma(k, 1): allow 4.5 sd
            // of the Gamma either way, and the cone filter's extra spread (about 12%) on top.
            const double z = 4.5 * (coneK > 0 ? 1.15 : 1.0) / std::sqrt(double(k));
            const double lo = 1 - z / (1 + z), hi = 1 + z / (1 - z);
            double mean = 0;
            const int queries = 50;
            for (int i = 0; i < queries; ++i) {
                const Vec3 q{0.2 + 0.6 * u(rng), 0.2 + 0.6 * u(rng), 0};
                const double e = map.irradiance(q, {0, 0, 1}, buffer, state, settings) / power;
                EXPECT_GT(e, lo) << "k " << k << " at " << q.x << ", " << q.y;
                EXPECT_LT(e, hi) << "k " << k << " at " << q.x << ", " << q.y;
                mean += e / queries;
            }
            // The mean: 4 sd of a mean of `queries` estimates, plus the k / (k - 1) bias of the box filter.
            EXPECT_NEAR(mean, 1.0, 4 * 1.15 / std::sqrt(double(k) * queries) + 1.0 / k);
        }
    }
}

TEST(PhotonMap, EstimateWeighsPhotonsByTheCallersFunction) {
    std::vector<Photon> photons;
    for (int i = 0; i < 100; ++i)
        photons.push_back(Photon::make({0.01 * i, 0, 0}, 1, kDown, i % 2 ? 450 : 650));
    const PhotonMap map(std::move(photons));
    std::vector<Neighbor> buffer(20);
    GatherState state;
    const double blue = map.estimate<double>(
        {0.5, 0, 0}, buffer, state, {}, [](const Photon& p) { return p.wavelength() < 500 ? 1.0 : 0.0; });
    const double all =
        map.estimate<double>({0.5, 0, 0}, buffer, state, {}, [](const Photon&) { return 1.0; });
    EXPECT_GT(all, 0);
    EXPECT_NEAR(blue / all, 0.5, 1e-9);
}

}  // namespace
}  // namespace facetlight
