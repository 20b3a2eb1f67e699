#include "trace/photon_tracer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "geometry/halfspace.h"
#include "intersect/convex_intersector.h"
#include "io/mesh_io.h"
#include "optics/fresnel.h"
#include "optics/material.h"
#include "stone/stone.h"
#include "support/fixtures.h"
#include "support/many_facet_stones.h"
#include "support/simd_targets.h"
#include "util/error.h"
#include "util/random.h"

using namespace facetlight;
using nlohmann::json;
using test::forEachSimdTarget;

namespace {

// A single cut: octagonal table, 8 bezels, 8 girdle flats and 8 pavilion mains, as half-spaces.
Stone singleCut() {
    std::vector<NamedPlane> planes{{{{0, 0, 1}, 0.17}, "table"}};
    for (int k = 0; k < 8; ++k) {
        const double a = radians(45.0 * k + 22.5);
        const Vec3 radial{std::cos(a), std::sin(a), 0};
        auto plane = [&](double slopeDeg, double zSign, double offset, const std::string& name) {
            const double s = radians(slopeDeg);
            planes.push_back(
                {{normalize(radial * std::sin(s) + Vec3{0, 0, zSign * std::cos(s)}), offset}, name});
        };
        plane(34.5, 1, 0.5 * std::sin(radians(34.5)), "bezel_" + std::to_string(k));
        plane(90, 0, 0.5, "girdle_" + std::to_string(k));
        plane(40.75, -1, 0.5 * std::sin(radians(40.75)), "pavilion_" + std::to_string(k));
    }
    return Stone::build(intersectHalfSpaces(planes), "single_cut");
}

// A shipped design (meshes/NAME.obj).
Stone shipped(const std::string& name) {
    return loadStone(std::string(FACETLIGHT_SOURCE_DIR) + "/meshes/" + name + ".obj");
}

TraceSettings baseSettings(uint64_t photons) {
    TraceSettings s;
    s.photons = photons;
    s.seed = 7;
    s.dispersion = false;
    return s;
}

void expectConservation(const FacetStats& s) {
    EXPECT_EQ(s.entered, s.exited + s.trapped + s.absorbed);
    EXPECT_EQ(s.hit, s.entered + s.reflectedAtEntry);
    uint64_t entering = 0, reflected = 0, leaving = 0;
    for (const FacetCounts& f : s.facets) {
        entering += f.entering;
        reflected += f.reflected;
        leaving += f.leaving;
    }
    EXPECT_EQ(entering, s.entered);
    EXPECT_EQ(reflected, s.reflectedAtEntry);
    EXPECT_EQ(leaving, s.exited);
    uint64_t histogram = 0;
    for (uint64_t c : s.histogram[0]) histogram += c;
    EXPECT_EQ(histogram, s.exited);
    EXPECT_LE(s.hit, s.photons);
}

const Facet& facetWithNormal(const Stone& stone, const Vec3& n) {
    for (const Facet& f : stone.facets) {
        if (dot(f.normal, n) > 0.999) return f;
    }
    throw Error("no such facet");
}

// Removes what may differ between runs of the same job with different thread counts.
json comparable(json j) {
    j.erase("timing");
    j["settings"].erase("threads");
    return j;
}

}  // namespace

TEST(Fresnel, NormalIncidenceIntoDiamond) {
    const float n = 2.4173f;
    const FresnelResult r = fresnel(1.0f, 1.0f / n);
    EXPECT_FALSE(r.totalInternal);
    EXPECT_NEAR(r.reflectance, 0.1720, 1e-4);
    EXPECT_NEAR(r.cosT, 1.0, 1e-6);
    // The same interface seen from inside reflects as much.
    EXPECT_NEAR(fresnel(1.0f, n).reflectance, 0.1720, 1e-4);
}

TEST(Fresnel, TotalInternalReflectionBeyondTheCriticalAngle) {
    const float n = 2.4173f;
    const double critical = degrees(std::asin(1.0 / n));
    EXPECT_NEAR(critical, 24.44, 0.01);
    const FresnelResult beyond = fresnel(float(std::cos(radians(critical + 0.1))), n);
    EXPECT_TRUE(beyond.totalInternal);
    EXPECT_EQ(beyond.reflectance, 1.0f);
    const FresnelResult within = fresnel(float(std::cos(radians(critical - 0.5))), n);
    EXPECT_FALSE(within.totalInternal);
    EXPECT_LT(within.reflectance, 1.0f);
    EXPECT_GT(within.reflectance, 0.1720f);  // rises toward 1 at the critical angle
    // Snell: n sin(ti) = sin(tt).
    const double ti = radians(critical - 0.5);
    EXPECT_NEAR(std::acos(within.cosT), std::asin(n * std::sin(ti)), 1e-3);
}

TEST(PhotonTracer, DiamondSlabAtNormalIncidence) {
    const Stone stone = test::unitCube();
    TraceSettings settings = baseSettings(400'000);
    settings.threads = 2;
    const TraceResult r = test::traceStone(stone, settings);
    ASSERT_FALSE(r.cancelled);
    const FacetStats& s = r.stats;
    expectConservation(s);
    EXPECT_EQ(s.photons, settings.photons);
    // The disc around the square silhouette has area pi/2; collimated light only meets the top.
    EXPECT_NEAR(double(s.hit) / double(s.photons), 2 / kPi, 4 * std::sqrt(0.64 * 0.36 / 400'000));

    const double n = Material::byName("diamond").indexD();
    const double R = (n - 1) * (n - 1) / ((n + 1) * (n + 1));
    ASSERT_NEAR(R, 0.1720, 1e-4);
    const Facet& top = facetWithNormal(stone, {0, 0, 1});
    const Facet& bottom = facetWithNormal(stone, {0, 0, -1});
    EXPECT_EQ(s.facets[top.id].entering, s.entered);
    const double up = double(s.facets[top.id].reflected + s.facets[top.id].leaving) / double(s.hit);
    const double down = double(s.facets[bottom.id].leaving) / double(s.hit);
    const double se = std::sqrt(0.2935 * 0.7065 / double(s.hit));
    EXPECT_NEAR(up, 2 * R / (1 + R), 4 * se);
    EXPECT_NEAR(down, (1 - R) / (1 + R), 4 * se);
    EXPECT_EQ(s.facets[top.id].leaving + s.facets[bottom.id].leaving, s.exited)
        << "no light reaches the sides";
    // Straight up and straight down only.
    EXPECT_EQ(s.histogram[0][0] + s.histogram[0][179], s.exited);

    const json j = statsToJson(s, stone, toJson(settings), r.timing);
    EXPECT_NEAR(j["totals"]["crown_return_with_reflection"].get<double>(), up, 1e-12);
    EXPECT_NEAR(j["totals"]["weighted_return"].get<double>(), j["totals"]["crown_return"].get<double>(),
                1e-6);
}

TEST(PhotonTracer, IdenticalForAnyThreadCount) {
    const Stone stone = singleCut();
    TraceSettings settings = baseSettings(3 * kPhotonBlock + 123);
    settings.dispersion = true;
    settings.light.model = LightModelKind::Hemisphere;
    settings.light.headShadowDeg = 15;
    json first;
    for (int threads : {1, 2, 3}) {
        settings.threads = threads;
        const TraceResult r = test::traceStone(stone, settings);
        expectConservation(r.stats);
        const json j = comparable(traceReport(r, stone, settings));
        if (threads == 1) {
            first = j;
        } else {
            EXPECT_EQ(j.dump(), first.dump()) << threads << " threads";
        }
    }
    EXPECT_GT(first["totals"]["crown_return"].get<double>(), 0.1);
}

TEST(PhotonTracer, BlockRangesMergeToTheWholeRun) {
    const Stone stone = singleCut();
    TraceSettings settings = baseSettings(5 * kPhotonBlock + 10);
    const Scene scene(stone, settings);
    const TraceBase trace(scene, settings);
    FacetStats whole(stone.facets.size()), a(stone.facets.size()), b(stone.facets.size());
    ASSERT_TRUE(traceBlocks(trace, 0, blockCount(settings.photons), 1, whole));
    ASSERT_TRUE(traceBlocks(trace, 0, 2, 2, a));
    ASSERT_TRUE(traceBlocks(trace, 2, 100, 1, b));
    b.merge(a);
    EXPECT_TRUE(b == whole);
    EXPECT_EQ(whole.photons, settings.photons);
}

TEST(PhotonTracer, ConvexAndEmbreeAgree) {
    const Stone stone = singleCut();
    ASSERT_TRUE(stone.convex);
    TraceSettings settings = baseSettings(200'000);
    settings.threads = 2;
    settings.light.model = LightModelKind::Hemisphere;
    settings.intersector = IntersectorKind::Convex;
    const TraceResult convex = test::traceStone(stone, settings);
    settings.intersector = IntersectorKind::Embree;
    ASSERT_TRUE(Scene(stone, settings).usesEmbree());
    const TraceResult embree = test::traceStone(stone, settings);
    expectConservation(convex.stats);
    expectConservation(embree.stats);
    EXPECT_EQ(embree.stats.lost, 0u);
    const json a = traceReport(convex, stone, settings)["totals"];
    const json b = traceReport(embree, stone, settings)["totals"];
    for (const char* figure : {"crown_return", "leakage", "cone_return_45", "weighted_return"}) {
        const double se = std::hypot(a[std::string(figure) + "_stderr"].get<double>(),
                                     b[std::string(figure) + "_stderr"].get<double>());
        EXPECT_NEAR(a[figure].get<double>(), b[figure].get<double>(), 4 * se) << figure;
    }
    // Same photons and same random streams: hits differ only where a ray grazes an edge.
    EXPECT_NEAR(double(convex.stats.hit), double(embree.stats.hit), 1e-4 * double(convex.stats.hit));
}

namespace {

// The counts a trace keeps, rebuilt from tracePhoton's path of each photon in turn.
FacetStats tallyOfPaths(const TraceBase& trace) {
    const Stone& stone = trace.scene().stone();
    const TraceSettings& settings = trace.settings();
    const double tilt = radians(settings.light.tiltDeg);
    const Vec3f up(Vec3{0, std::sin(tilt), std::cos(tilt)});
    const ExitAngleBins exitBin;
    FacetStats stats(stone.facets.size());
    uint64_t bounces = 0;
    for (uint64_t i = 0; i < settings.photons; ++i) {
        PhotonPath path;
        tracePhoton(trace, i, path);
        ++stats.photons;
        bounces += path.bounces;
        switch (path.outcome) {
            case PhotonOutcome::Missed:
                break;
            case PhotonOutcome::ReflectedAtEntry:
                ++stats.hit, ++stats.reflectedAtEntry, ++stats.facets[path.exitFacet].reflected;
                break;
            case PhotonOutcome::Trapped:
                ++stats.hit, ++stats.entered, ++stats.facets[path.entryFacet].entering, ++stats.trapped;
                break;
            case PhotonOutcome::Absorbed:
                ++stats.hit, ++stats.entered, ++stats.facets[path.entryFacet].entering, ++stats.absorbed;
                break;
            case PhotonOutcome::Exited: {
                ++stats.hit, ++stats.entered, ++stats.facets[path.entryFacet].entering, ++stats.exited;
                ++stats.facets[path.exitFacet].leaving;
                const float cosUp = std::clamp(dot(path.exitDirection, up), -1.0f, 1.0f);
                ++stats.histogram[0][exitBin(cosUp)];
                const Region r = stone.facets[path.exitFacet].region;
                if ((r == Region::Table || r == Region::Crown) && cosUp > 0) {
                    ++stats.crownReturn;
                    stats.weightSum += uint64_t(double(cosUp) * kWeightScale + 0.5);
                }
                break;
            }
        }
    }
    // Each internal reflection is a bounce of the photon that made it.
    stats.facets[0].internalReflections = bounces;
    return stats;
}

void expectTracePhotonReproducesTheTally(const Stone& stone) {
    struct Case {
        const char* what;
        LightModelKind light;
        bool dispersion;
        double tiltDeg;
        int maxBounces;
        SkyKind sky = SkyKind::Uniform;
        PolarizationMode polarization = PolarizationMode::Off;
        std::optional<double> polarizerDeg = std::nullopt;
        bool absorbing = false;
        std::string material = "diamond";
        double opticAxisTiltDeg = 0;
        double opticAxisRotationDeg = 0;
    };
    // Absorbing more at the ends of the spectrum, differently for the extraordinary wave.
    const AbsorptionSpectrum spectrum{{400, 550, 700}, {0.3, 0.05, 0.15}, {0.1, 0.25, 0.02}};
    const AbsorptionSpectrum isotropic{spectrum.wavelengthNm, spectrum.ordinaryPerMm, {}};
    const auto U = SkyKind::Uniform;
    const auto On = PolarizationMode::On, Off = PolarizationMode::Off;
    for (const Case& c :
         {Case{"collimated", LightModelKind::Collimated, false, 0, 64},
          Case{"collimated, tilted, dispersion", LightModelKind::Collimated, true, 20, 64},
          Case{"hemisphere, dispersion", LightModelKind::Hemisphere, true, 0, 64},
          Case{"hemisphere, cosine sky", LightModelKind::Hemisphere, false, 0, 64, SkyKind::Cosine},
          Case{"point, 3 bounces at most", LightModelKind::Point, false, 0, 3},
          Case{"polarised, hemisphere, dispersion", LightModelKind::Hemisphere, true, 0, 64, SkyKind::Uniform,
               PolarizationMode::On},
          Case{"polarised, collimated through a polariser, tilted", LightModelKind::Collimated, false, 20, 64,
               SkyKind::Uniform, PolarizationMode::On, 30.0},
          Case{"absorbing, collimated", LightModelKind::Collimated, false, 0, 64, U, Off, {}, true},
          Case{"absorbing, collimated, tilted, dispersion",
               LightModelKind::Collimated,
               true,
               20,
               64,
               U,
               Off,
               {},
               true},
          Case{
              "absorbing, hemisphere, dispersion", LightModelKind::Hemisphere, true, 0, 64, U, Off, {}, true},
          Case{"absorbing, polarised, hemisphere, dispersion",
               LightModelKind::Hemisphere,
               true,
               0,
               64,
               U,
               On,
               {},
               true},
          Case{"absorbing tourmaline, o/e mixture, collimated, dispersion",
               LightModelKind::Collimated,
               true,
               10,
               64,
               U,
               Off,
               {},
               true,
               "tourmaline"},
          Case{"absorbing tourmaline, birefringent, hemisphere",
               LightModelKind::Hemisphere,
               true,
               0,
               64,
               U,
               On,
               {},
               true,
               "tourmaline"},
          // The crystal packet walk: the axis tilted so that no wave is near it, and near it (the coherent
          // zone, reflections along the table's normal), absorbing, through a polariser; and a biaxial stone.
          Case{"sapphire, tilted axis, collimated, tilted, dispersion, 6 bounces at most",
               LightModelKind::Collimated,
               true,
               20,
               6,
               U,
               On,
               {},
               false,
               "sapphire",
               35},
          Case{"absorbing sapphire, axis on the table's normal, hemisphere",
               LightModelKind::Hemisphere,
               false,
               0,
               64,
               U,
               On,
               {},
               true,
               "sapphire"},
          Case{"absorbing sapphire, tilted axis, collimated through a polariser, 5 bounces at most",
               LightModelKind::Collimated, true, 0, 5, U, On, 30.0, true, "sapphire", 60},
          Case{"topaz, turned axes, hemisphere, dispersion, 6 bounces at most",
               LightModelKind::Hemisphere,
               true,
               0,
               6,
               U,
               On,
               {},
               false,
               "topaz",
               25,
               40}}) {
        SCOPED_TRACE(c.what);
        TraceSettings settings = baseSettings(2 * kPhotonBlock + 1000);
        settings.light.model = c.light;
        settings.light.sky = c.sky;
        settings.light.tiltDeg = c.tiltDeg;
        settings.dispersion = c.dispersion;
        settings.maxBounces = c.maxBounces;
        settings.polarization = c.polarization;
        settings.light.polarizerDeg = c.polarizerDeg;
        settings.material = c.material;
        settings.opticAxis.tiltDeg = c.opticAxisTiltDeg;
        settings.opticAxis.rotationDeg = c.opticAxisRotationDeg;
        if (c.absorbing) settings.absorption = c.material == "diamond" ? isotropic : spectrum;
        const Scene scene(stone, settings);
        const TraceBase trace(scene, settings);
        ASSERT_EQ(trace.absorbs(), c.absorbing);
        FacetStats traced(stone.facets.size());
        traceBlocks(trace, 0, blockCount(settings.photons), 1, traced);
        const FacetStats paths = tallyOfPaths(trace);
        EXPECT_EQ(paths.photons, traced.photons);
        EXPECT_EQ(paths.hit, traced.hit);
        EXPECT_EQ(paths.reflectedAtEntry, traced.reflectedAtEntry);
        EXPECT_EQ(paths.exited, traced.exited);
        EXPECT_EQ(paths.trapped, traced.trapped);
        EXPECT_EQ(paths.absorbed, traced.absorbed);
        EXPECT_EQ(paths.crownReturn, traced.crownReturn);
        EXPECT_EQ(paths.weightSum, traced.weightSum);
        EXPECT_EQ(paths.histogram[0], traced.histogram[0]);
        uint64_t internalReflections = 0;
        for (size_t f = 0; f < stone.facets.size(); ++f) {
            EXPECT_EQ(paths.facets[f].entering, traced.facets[f].entering) << f;
            EXPECT_EQ(paths.facets[f].reflected, traced.facets[f].reflected) << f;
            EXPECT_EQ(paths.facets[f].leaving, traced.facets[f].leaving) << f;
            internalReflections += traced.facets[f].internalReflections;
        }
        EXPECT_EQ(paths.facets[0].internalReflections, internalReflections);
        expectConservation(traced);
        if (c.absorbing) {
            EXPECT_GT(traced.absorbed, traced.hit / 20);
        } else {
            EXPECT_GT(traced.trapped, 0u);
            EXPECT_EQ(traced.absorbed, 0u);
        }
    }
}

}  // namespace

// The whole-block trace (a packet of photons per SIMD register) and the one-photon path follow each photon
// through the same steps with the same bits, on every SIMD target.
TEST(PhotonTracer, TracePhotonReproducesTheTally) {
    const Stone plain = singleCut(), girdled = shipped("round_brilliant");
    ASSERT_FALSE(ConvexIntersector(plain).girdle());
    ASSERT_TRUE(ConvexIntersector(girdled).girdle());  // the exit search skips its girdle where it can
    forEachSimdTarget([&] {
        for (const Stone* stone : {&plain, &girdled}) {
            SCOPED_TRACE(stone->name);
            expectTracePhotonReproducesTheTally(*stone);
        }
    });
}

// Every target gives every ray of the renderer and tracePhoton the same hit, bit for bit, and the one a
// plain loop over the planes gives (the contract of convex_intersector.h).
TEST(ConvexIntersector, SameHitsOnEveryTarget) {
    const Stone stone = singleCut();
    struct Hits {
        std::vector<uint32_t> t;  // bit patterns
        std::vector<uint32_t> facet;
        bool operator==(const Hits&) const = default;
    };
    auto cast = [&](Hits& hits) {
        const ConvexIntersector convex(stone);
        const Vec3f beamDir(Vec3{normalize(Vec3{0.3, -0.2, -1})});
        const ConvexBeamEntry beam(stone, beamDir);
        Rng rng(7, 1);
        auto draw = [&] { return 1.4f * rng.uniform() - 0.7f; };
        for (int i = 0; i < 20'000; ++i) {
            const Vec3f inside{0.5f * draw(), 0.5f * draw(), 0.2f * draw()};
            const Vec3f outside = Vec3f{draw(), draw(), draw()} * 3.0f;
            const Vec3f dir = normalize(Vec3f{draw(), draw(), draw()});
            const Vec3f beamOrigin = Vec3f{draw(), draw(), 1.0f} - beamDir * 2.0f;
            SurfaceHit leaving, entering, beamEntering;
            const bool found[3] = {convex.leave(inside, dir, leaving),
                                   convex.enter(outside, -outside, entering),
                                   beam.enter(beamOrigin, beamEntering)};
            const SurfaceHit* hit[3] = {&leaving, &entering, &beamEntering};
            for (int k = 0; k < 3; ++k) {
                hits.t.push_back(found[k] ? std::bit_cast<uint32_t>(hit[k]->t) : 0xffffffffu);
                hits.facet.push_back(found[k] ? hit[k]->facet : 0xffffffffu);
            }
        }
    };
    Hits first;
    cast(first);
    forEachSimdTarget([&] {
        Hits hits;
        cast(hits);
        EXPECT_TRUE(hits == first);
    });
    // The exits of the first 1000 rays from a plain loop: the smallest num / den over the planes with den >
    // 0, the lowest facet on ties, 0 for a point a rounding error outside.
    Rng rng(7, 1);
    auto draw = [&] { return 1.4f * rng.uniform() - 0.7f; };
    for (int i = 0; i < 1000; ++i) {
        const Vec3f o{0.5f * draw(), 0.5f * draw(), 0.2f * draw()};
        for (int k = 0; k < 3; ++k) draw();  // the entry ray's
        const Vec3f d = normalize(Vec3f{draw(), draw(), draw()});
        for (int k = 0; k < 2; ++k) draw();  // the beam ray's
        float best = INFINITY;
        uint32_t facet = 0;
        for (size_t f = 0; f < stone.facets.size(); ++f) {
            const Vec3f n(stone.facets[f].normal);
            const float den = dot(d, n), t = (float(stone.facets[f].offset) - dot(o, n)) / den;
            if (den > 0 && (t > 0 ? t : 0.0f) < best) best = t > 0 ? t : 0.0f, facet = uint32_t(f);
        }
        EXPECT_EQ(first.t[3 * i], std::bit_cast<uint32_t>(best)) << i;
        EXPECT_EQ(first.facet[3 * i], facet) << i;
    }
}

namespace {

// The exit through every plane by a plain loop: the smallest num / den over the planes with den > 0, the
// lowest facet on ties, 0 for a point a rounding error outside; t = +inf and facet 0 where there is none.
SurfaceHit exitOverEveryPlane(const Stone& stone, const Vec3f& o, const Vec3f& d) {
    SurfaceHit best{INFINITY, 0};
    for (const Facet& f : stone.facets) {
        const Vec3f n(f.normal);
        const float den = dot(d, n), t = (float(f.offset) - dot(o, n)) / den, leaving = t > 0 ? t : 0.0f;
        if (den > 0 && leaving < best.t) best = {leaving, f.id};
    }
    return best;
}

// On every SIMD target, the stone's exit search gives each ray the exit through every plane, bit for bit.
void expectExitsOverEveryPlane(const Stone& stone, const std::vector<std::pair<Vec3f, Vec3f>>& rays) {
    forEachSimdTarget([&] {
        const ConvexIntersector onTarget(stone);
        size_t wrong = 0;
        for (const auto& [o, d] : rays) {
            SurfaceHit hit;
            const bool found = onTarget.leave(o, d, hit);
            const SurfaceHit every = exitOverEveryPlane(stone, o, d);
            wrong += found != (every.t < INFINITY) ||
                     std::bit_cast<uint32_t>(hit.t) != std::bit_cast<uint32_t>(every.t) ||
                     hit.facet != every.facet;
        }
        EXPECT_EQ(wrong, 0u) << "of " << rays.size();
    });
}

// Rays that try the girdle split: walks of reflections from random inside points, rays from points on the
// girdle and parallel to its planes, rays through vertices and edges (ties), points a rounding error
// outside, directions far from unit length, zero and NaN.
std::vector<std::pair<Vec3f, Vec3f>> testRays(const Stone& stone, const ConvexIntersector& convex) {
    std::vector<std::pair<Vec3f, Vec3f>> rays;
    Rng rng(11, 3);
    auto unit = [&] {
        for (;;) {
            const Vec3f v(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1);
            if (dot(v, v) > 0.01f && dot(v, v) <= 1) return normalize(v);
        }
    };
    const Vec3f center(stone.bounds.center());
    for (int walk = 0; walk < 1500; ++walk) {
        const Vec3 v = stone.vertices[size_t(rng.uniform() * float(stone.vertices.size()))];
        Vec3f o = center + (Vec3f(v) - center) * rng.uniform(), d = unit();
        for (int bounce = 0; bounce < 6; ++bounce) {
            rays.push_back({o, d});
            SurfaceHit hit;
            if (!convex.leave(o, d, hit)) break;
            const Vec3f n(stone.facets[hit.facet].normal);
            o = o + d * hit.t;
            d = d - n * (2 * dot(d, n));
        }
    }
    for (const Facet& f : stone.facets) {
        const Vec3f n(f.normal), along = normalize(Vec3f(-n.y, n.x, 0.0f));
        for (uint32_t a : f.outline) {
            for (uint32_t b : f.outline) {
                const Vec3f onFacet = (Vec3f(stone.vertices[a]) + Vec3f(stone.vertices[b])) * 0.5f;
                rays.push_back({onFacet, unit()});
                rays.push_back({onFacet, along});  // parallel to the facet's plane when it is upright
                rays.push_back({onFacet, along * -1.0f});
                rays.push_back({center, onFacet - center});  // through an edge or a vertex: ties
                rays.push_back({center, normalize(onFacet - center)});
                rays.push_back({onFacet + n * 1e-6f, unit()});  // just outside
                rays.push_back({onFacet, unit() * 3.0f});
                rays.push_back({onFacet, unit() * 0.1f});
            }
        }
    }
    rays.push_back({center, Vec3f(0, 0, 0)});
    rays.push_back({center, Vec3f(NAN, 0, 1)});
    rays.push_back({Vec3f(1e30f, 0, 0), Vec3f(0, 0, 1)});
    return rays;
}

}  // namespace

// The exit search that skips a round stone's girdle where it cannot be the answer gives, bit for bit, the
// exit through every plane, on every target, one ray at a time and a packet at a time (the packet walk: test
// above).
TEST(ConvexIntersector, GirdleSkipGivesTheExitThroughEveryPlane) {
    const std::vector<std::string> round = {"round_brilliant", "round_brilliant_deep", "old_european"};
    std::vector<std::string> names = round;
    names.insert(names.end(), {"single_cut", "rose_cut", "oval", "pear", "round_brilliant_tolkowsky"});
    for (const std::string& name : names) {
        SCOPED_TRACE(name);
        const Stone stone = shipped(name);
        const ConvexIntersector convex(stone);
        if (std::find(round.begin(), round.end(), name) != round.end()) {
            ASSERT_TRUE(convex.girdle());
            EXPECT_EQ(convex.girdle()->facets.count, 64u);
        }
        std::printf("%s: %zu girdle facets searched apart\n", name.c_str(),
                    convex.girdle() ? convex.girdle()->facets.count : 0);
        const std::vector<std::pair<Vec3f, Vec3f>> rays = testRays(stone, convex);
        expectExitsOverEveryPlane(stone, rays);
    }
}

// Stones of many facets and no round girdle search their planes in groups (ConvexIntersector::Cull) and get,
// bit for bit, the exit through every plane, on every target: the rays of testRays (walks, points on facets,
// ties through edges and vertices, points a rounding error outside, odd lengths, zero and NaN) and rays
// from random points inside and on the surface in random directions.
TEST(ConvexIntersector, CullGivesTheExitThroughEveryPlane) {
    for (const Stone& stone : {test::briolette(), test::checkerboard(), test::stepCut217()}) {
        SCOPED_TRACE(stone.name);
        EXPECT_GE(stone.facets.size(), 217u);
        const ConvexIntersector convex(stone);
        ASSERT_FALSE(convex.girdle());
        ASSERT_TRUE(convex.cull());
        std::printf("%s: %zu facets in %zu groups\n", stone.name.c_str(), stone.facets.size(),
                    convex.cull()->groups.size());
        std::vector<std::pair<Vec3f, Vec3f>> rays = testRays(stone, convex);
        Rng rng(5, 9);
        const Vec3f center(stone.bounds.center());
        for (int i = 0; i < 100'000; ++i) {
            const Facet& f = stone.facets[size_t(rng.uniform() * float(stone.facets.size()))];
            const Vec3 a = stone.vertices[f.outline[0]], b = stone.vertices[f.outline[1]],
                       c = stone.vertices[f.outline[2]];
            const double u = rng.uniform(), v = rng.uniform() * (1 - u);
            const Vec3f onSurface(a + (b - a) * u + (c - a) * v);
            const Vec3f inside = center + (onSurface - center) * rng.uniform();
            const Vec3f d =
                normalize(Vec3f(2 * rng.uniform() - 1, 2 * rng.uniform() - 1, 2 * rng.uniform() - 1));
            rays.push_back({i % 2 ? inside : onSurface, d});
        }
        expectExitsOverEveryPlane(stone, rays);
    }
}

// The whole trace of each many-facet stone (the packet walk, whose exits the Cull finds one ray at a time)
// tallies the same with the Cull as with the search over every plane, on every target; and the one-photon
// walk reproduces the tally.
TEST(PhotonTracer, CullKeepsTheTally) {
    TraceSettings settings = baseSettings(2 * kPhotonBlock + 1000);
    settings.light.model = LightModelKind::Hemisphere;
    settings.dispersion = true;
    for (const Stone& stone : {test::briolette(), test::checkerboard(), test::stepCut217()}) {
        SCOPED_TRACE(stone.name);
        forEachSimdTarget([&] {
            ConvexIntersector::setCulling(false);
            const TraceResult every = test::traceStone(stone, settings);
            ConvexIntersector::setCulling(true);
            const Scene scene(stone, settings);
            ASSERT_TRUE(scene.convex()->cull());
            const TraceBase base(scene, settings);
            const TraceResult culled = trace(base);
            EXPECT_GT(culled.stats.exited, 0u);
            EXPECT_TRUE(culled.stats == every.stats);
            const FacetStats paths = tallyOfPaths(base);
            EXPECT_EQ(paths.exited, culled.stats.exited);
            for (size_t f = 0; f < stone.facets.size(); ++f) {
                EXPECT_EQ(paths.facets[f].leaving, culled.stats.facets[f].leaving) << f;
                EXPECT_EQ(paths.facets[f].reflected, culled.stats.facets[f].reflected) << f;
            }
        });
    }
}

// Tolkowsky's second reflection in 2-D: a long trough (a table over two pavilion facets at slope P) under
// vertical light. A photon that enters the table, reflects totally off one pavilion facet (incidence P) and
// then the other (incidence 180 - 3P) meets the table at 180 - 4P from the vertical, and stays in by total
// reflection while that exceeds the critical angle: P < (180 - 24.44) / 4 = 38.89 deg (docs/optics.md).
TEST(PhotonTracer, SecondReflectionLeavesTheTableOnlyAboveTheThreshold) {
    auto tableExitsAfterTwoReflections = [](double pavilionDeg, double& exitAngleDeg) {
        const double p = radians(pavilionDeg);
        std::vector<NamedPlane> planes{{{{0, 0, 1}, 0}, "table"},
                                       {{{std::sin(p), 0, -std::cos(p)}, 0.5 * std::sin(p)}, "pavilion_a"},
                                       {{{-std::sin(p), 0, -std::cos(p)}, 0.5 * std::sin(p)}, "pavilion_b"},
                                       {{{0, 1, 0}, 1}, "end_a"},
                                       {{{0, -1, 0}, 1}, "end_b"}};  // vertical light never meets the ends
        const Stone trough = Stone::build(intersectHalfSpaces(planes), "trough");
        TraceSettings settings = baseSettings(20'000);
        settings.constantIndex = 2.4173;
        const Scene scene(trough, settings);
        const TraceBase trace(scene, settings);
        int count = 0;
        exitAngleDeg = 0;
        for (uint64_t i = 0; i < settings.photons; ++i) {
            PhotonPath path;
            tracePhoton(trace, i, path);
            if (path.outcome != PhotonOutcome::Exited || path.bounces != 2) continue;
            if (trough.facets[path.exitFacet].region != Region::Table) continue;
            ++count;
            exitAngleDeg = degrees(std::acos(std::clamp(double(path.exitDirection.z), -1.0, 1.0)));
        }
        return count;
    };
    double angle = 0;
    EXPECT_EQ(tableExitsAfterTwoReflections(38.75, angle), 0) << "180 - 4P = 25 deg: totally reflected";
    EXPECT_GT(tableExitsAfterTwoReflections(39.0, angle), 1000) << "180 - 4P = 24 deg: out through the table";
    EXPECT_NEAR(angle, degrees(std::asin(2.4173 * std::sin(radians(24.0)))), 0.01);  // Snell at the table
}

TEST(PhotonTracer, ExitPathsLeaveThroughTheirFacet) {
    const Stone stone = singleCut();
    const Scene scene(stone, baseSettings(2000));
    const TraceBase trace(scene, baseSettings(2000));
    for (uint64_t i = 0; i < 2000; ++i) {
        PhotonPath path;
        tracePhoton(trace, i, path);
        if (path.outcome != PhotonOutcome::Exited) continue;
        EXPECT_NEAR(std::sqrt(dot(path.exitDirection, path.exitDirection)), 1.0, 1e-5);
        const Facet& f = stone.facets[path.exitFacet];
        EXPECT_NEAR(dot(Vec3{path.exitPosition.x, path.exitPosition.y, path.exitPosition.z}, f.normal),
                    f.offset, 1e-4);
        EXPECT_GT(dot(Vec3{path.exitDirection.x, path.exitDirection.y, path.exitDirection.z}, f.normal), 0);
    }
}

TEST(PhotonTracer, LightModelsAndTiltKeepConservation) {
    const Stone stone = singleCut();
    for (LightModelKind model :
         {LightModelKind::Collimated, LightModelKind::Hemisphere, LightModelKind::Point}) {
        TraceSettings settings = baseSettings(20'000);
        settings.light.model = model;
        settings.light.tiltDeg = 20;
        settings.maxBounces = 3;
        const TraceResult r = test::traceStone(stone, settings);
        expectConservation(r.stats);
        EXPECT_GT(r.stats.trapped, 0u) << "a bounce limit of 3 traps some photons";
        EXPECT_GT(r.stats.hit, r.stats.photons / 4) << "photons are aimed at the stone";
    }
}

TEST(PhotonTracer, CollimatedStraightDownHitsAlmostEveryPhoton) {
    const Stone stone = singleCut();
    const TraceResult r = test::traceStone(stone, baseSettings(20'000));
    // The disc circumscribes the octagonal girdle: cos(22.5 deg)^2 * (8 tan(22.5) / pi) of it is stone.
    const double octagonShare = 8 * std::tan(radians(22.5)) * std::pow(std::cos(radians(22.5)), 2) / kPi;
    EXPECT_NEAR(double(r.stats.hit) / double(r.stats.photons), octagonShare, 0.01);
}

// Issue 18: a direction of 1e308 components normalised to zero and "succeeded" with no photon hitting.
TEST(PhotonTracer, HugeDirectionIsTheSameDirection) {
    const Stone stone = singleCut();
    TraceSettings huge = baseSettings(2'000);
    huge.light.direction = {1e308, 1e308, -1e308};
    TraceSettings unit = huge;
    unit.light.direction = {1, 1, -1};
    const TraceResult a = test::traceStone(stone, huge), b = test::traceStone(stone, unit);
    EXPECT_GT(a.stats.hit, 0u);
    EXPECT_EQ(a.stats.hit, b.stats.hit);
    EXPECT_EQ(a.stats.tallies(), b.stats.tallies());
}

// Issue 18: a point light at 1e308 "succeeded" with no photon hitting. Settings read from JSON refuse
// coordinates beyond 1e9; the light model refuses a light further than 10^4 stone radii.
TEST(PhotonTracer, FarPointLightIsRefused) {
    const Stone stone = singleCut();
    TraceSettings settings = baseSettings(100);
    settings.light.model = LightModelKind::Point;
    for (const Vec3& far : {Vec3{0, 0, 1e308}, Vec3{1e308, 1e308, 1e308}, Vec3{0, 0, 1e6}}) {
        settings.light.position = far;
        try {
            test::traceStone(stone, settings);
            ADD_FAILURE() << "a point light at " << far.z << " was accepted";
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find("light.position must lie within 10000 stone radii"),
                      std::string::npos)
                << e.what();
        }
    }
    try {
        TraceSettings::fromJson(json{{"light", {{"model", "point"}, {"position", {0, 0, 1e308}}}}});
        ADD_FAILURE() << "a light position of 1e308 was read";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()), "light.position must be finite, each coordinate within 1e9");
    }
    settings.light.position = {0, 0, 100};
    EXPECT_GT(test::traceStone(stone, settings).stats.hit, 0u);
}

TEST(ExitAngleBins, MatchAcosExceptAtBinBoundaries) {
    const ExitAngleBins bin;
    EXPECT_EQ(bin(1.0f), 0);
    EXPECT_EQ(bin(-1.0f), kHistogramBins - 1);
    EXPECT_EQ(bin(0.0f), 90);
    EXPECT_EQ(bin(1.5f), 0);  // rounding past 1 clamps
    int checked = 0;
    for (int i = 0; i <= 400'000; ++i) {
        const float c = -1.0f + 2.0f * float(i) / 400'000;
        const double deg = std::acos(double(c)) * 180 / kPi;
        if (std::abs(deg - std::round(deg)) < 1e-4) continue;  // float cosines of k degrees decide these
        ASSERT_EQ(bin(c), std::min(kHistogramBins - 1, int(deg))) << c;
        ++checked;
    }
    EXPECT_GT(checked, 399'000);
}

TEST(ConvexBeamEntry, AgreesWithTheGeneralEntrySearch) {
    const Stone stone = singleCut();  // its girdle flats are parallel to vertical light
    const ConvexIntersector general(stone);
    for (const Vec3f dir : {Vec3f(0, 0, -1), Vec3f(Vec3{normalize(Vec3{0.3, -0.2, -1})})}) {
        const ConvexBeamEntry beam(stone, dir);
        Rng rng(1, 2);
        int hits = 0, disagree = 0;
        for (int i = 0; i < 20'000; ++i) {
            const Vec3f o =
                Vec3f(1.2f * rng.uniform() - 0.6f, 1.2f * rng.uniform() - 0.6f, 0.5f) - dir * 0.5f;
            SurfaceHit a, b;
            const bool ha = general.enter(o, dir, a), hb = beam.enter(o, b);
            disagree += ha != hb;
            if (!ha || !hb) continue;
            ++hits;
            EXPECT_NEAR(a.t, b.t, 1e-5);
            disagree += a.facet != b.facet;
        }
        EXPECT_GT(hits, 10'000);
        EXPECT_LE(disagree, 2);  // only rays grazing an edge may differ by a rounding error
    }
}

TEST(PhotonTracer, CancelStopsBeforeTheEnd) {
    const Stone stone = test::unitCube();
    RunControl control;
    control.cancel();
    const TraceResult r = test::traceStone(stone, baseSettings(100'000), &control);
    EXPECT_TRUE(r.cancelled);
    EXPECT_EQ(r.stats.photons, 0u);
    EXPECT_EQ(control.done(), 0u);

    RunControl progress;
    const TraceResult full = test::traceStone(stone, baseSettings(10'000), &progress);
    EXPECT_FALSE(full.cancelled);
    EXPECT_EQ(progress.done(), 10'000u);
}

TEST(PhotonTracer, ConvexIntersectorRefusesNonConvexRequest) {
    Stone stone = test::unitCube();
    stone.convex = false;
    TraceSettings settings = baseSettings(10);
    settings.intersector = IntersectorKind::Convex;
    EXPECT_THROW(Scene(stone, settings), Error);
    settings.intersector = IntersectorKind::Auto;
    EXPECT_TRUE(Scene(stone, settings).usesEmbree());
}

TEST(TraceSettings, JsonRoundTrip) {
    TraceSettings s = baseSettings(12345);
    s.threads = 3;
    s.constantIndex = 2.0;
    s.light.model = LightModelKind::Point;
    s.light.position = {1, 2, 30};
    s.intersector = IntersectorKind::Embree;
    const TraceSettings back = TraceSettings::fromJson(toJson(s));
    EXPECT_EQ(toJson(back).dump(), toJson(s).dump());
    EXPECT_EQ(TraceSettings::fromJson(json{{"photons", 1e6}}).photons, 1'000'000u);
}

TEST(TraceSettings, StrictJsonNamesTheField) {
    auto expectError = [](const json& j, const std::string& fragment) {
        try {
            TraceSettings::fromJson(j);
            FAIL() << j.dump();
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    expectError(json{{"photons", 0}}, "photons");
    expectError(json{{"photons", 2e10}}, "photons");
    expectError(json{{"photons", 1.5}}, "photons");
    // Issue 18: 2^64 written as a float passed the range check and converted with undefined behaviour.
    expectError(json{{"seed", 1.8446744073709552e19}}, "seed must be an integer");
    expectError(json{{"seed", -1}}, "seed must be an integer");
    expectError(json{{"photons", "many"}}, "photons");
    expectError(json{{"threads", -1}}, "threads");
    expectError(json{{"colour", "red"}}, "colour");
    expectError(json{{"light", {{"model", "laser"}}}}, "light.model");
    expectError(json{{"light", {{"tilt", 3}}}}, "light.tilt");
    expectError(json{{"light", {{"head_shadow_deg", 95}}}}, "light.head_shadow_deg");
    expectError(json{{"light", {{"direction", {0, 0}}}}}, "light.direction");
    expectError(json{{"material", "unobtainium"}}, "material");
    expectError(json{{"n", 0.5}}, "n must");
    expectError(json{{"dispersion", 1}}, "dispersion");
    expectError(json{{"intersector", "bvh"}}, "intersector");
    expectError(json::array(), "settings");
}

TEST(FacetStats, JsonAndCsvReport) {
    const Stone stone = test::unitCube();
    TraceSettings settings = baseSettings(10'000);
    const TraceResult r = test::traceStone(stone, settings);
    json j = traceReport(r, stone, settings);
    addShareStandardErrors(j);
    for (const char* key :
         {"mesh", "settings", "timing", "totals", "regions", "facets", "exit_angle_histogram"}) {
        EXPECT_TRUE(j.contains(key)) << key;
    }
    EXPECT_EQ(j["facets"].size(), stone.facets.size());
    EXPECT_EQ(j["exit_angle_histogram"]["crown"].size(), 180u);
    EXPECT_EQ(j["totals"]["hit"].get<uint64_t>(),
              j["totals"]["entered"].get<uint64_t>() + j["totals"]["reflected_at_entry"].get<uint64_t>());
    // Shares of `hit` with their binomial standard errors, sqrt(p (1 - p) / hit).
    const double hit = double(r.stats.hit);
    const auto binomialStderr = [&](double p) { return std::sqrt(p * (1 - p) / hit); };
    uint64_t regionLeaving = 0;
    for (const auto& [name, region] : j["regions"].items()) {
        regionLeaving += region["leaving"].get<uint64_t>();
        const double p = region["leaving"].get<double>() / hit;
        EXPECT_DOUBLE_EQ(region["share"].get<double>(), p) << name;
        EXPECT_DOUBLE_EQ(region["share_stderr"].get<double>(), binomialStderr(p)) << name;
    }
    EXPECT_EQ(regionLeaving, r.stats.exited);
    for (const json& f : j["facets"]) {
        EXPECT_DOUBLE_EQ(f["leaving_share_stderr"].get<double>(),
                         binomialStderr(f["leaving_share"].get<double>()))
            << f["name"];
    }
    std::ostringstream csv;
    writeFacetCsv(csv, r.stats, stone);
    const std::string text = csv.str();
    EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), long(stone.facets.size() + 1));
    EXPECT_EQ(text.rfind("id,name,region,area", 0), 0u);
}
