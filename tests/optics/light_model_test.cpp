// The light models against numbers worked out without the tracer: a wide flat slab's first-surface
// reflection under the hemisphere's two skies, with and without a head cone.
#include "optics/light_model.h"

#include <gtest/gtest.h>

#include <cmath>

#include "geometry/halfspace.h"
#include "support/fixtures.h"
#include "trace/photon_tracer.h"
#include "util/error.h"

using namespace facetlight;

namespace {

// 100 x 100 x 1: the sides are counted apart, so the top stands for an infinite flat surface.
Stone wideSlab() {
    std::vector<NamedPlane> planes{{{{0, 0, 1}, 0.5}, "top"},   {{{0, 0, -1}, 0.5}, "bottom"},
                                   {{{1, 0, 0}, 50}, "side_1"}, {{{-1, 0, 0}, 50}, "side_2"},
                                   {{{0, 1, 0}, 50}, "side_3"}, {{{0, -1, 0}, 50}, "side_4"}};
    return Stone::build(intersectHalfSpaces(planes), "slab");
}

struct SkyCase {
    SkyKind sky;
    double headShadowDeg;
    // The cosine-weighted average of the Fresnel reflectance R(theta) at n = 2.4173 over the sky's radiance
    // L(theta): integral of R L cos sin / integral of L cos sin, theta from the cone to 90 deg (numerical
    // quadrature). Uniform dome (L = 1): 0.2122, and 0.2135 less a 10-deg cone (docs/optics.md, from the
    // shared optics reference); cos(theta) sky (L = cos): 0.1902, and 0.1911 less the cone (our quadrature,
    // docs/physics.md).
    double firstSurfaceReflection;
};

class SlabUnderTheSky : public ::testing::TestWithParam<SkyCase> {};

TEST_P(SlabUnderTheSky, FirstSurfaceReflectionMatchesTheQuadrature) {
    static const Stone slab = wideSlab();
    const SkyCase& c = GetParam();
    TraceSettings s;
    s.photons = 4'000'000;
    s.threads = 2;
    s.seed = 11;
    s.constantIndex = 2.4173;
    s.dispersion = false;
    s.maxBounces = 1;  // only the first surface matters: photons that enter are done with at once
    s.light.model = LightModelKind::Hemisphere;
    s.light.sky = c.sky;
    s.light.headShadowDeg = c.headShadowDeg;
    const TraceResult r = test::traceStone(slab, s);
    const Facet* top = nullptr;
    for (const Facet& f : slab.facets)
        if (f.name == "top") top = &f;
    ASSERT_NE(top, nullptr);
    const FacetCounts& counts = r.stats.facets[top->id];
    const double hits = double(counts.reflected + counts.entering);
    const double reflected = double(counts.reflected) / hits;
    const double stderr = std::sqrt(reflected * (1 - reflected) / hits);
    EXPECT_GT(hits, 1e6);
    EXPECT_NEAR(reflected, c.firstSurfaceReflection, 4 * stderr)
        << kSkyNames.name(c.sky) << " sky, head cone " << c.headShadowDeg << " deg";
}

INSTANTIATE_TEST_SUITE_P(Skies, SlabUnderTheSky,
                         ::testing::Values(SkyCase{SkyKind::Uniform, 0, 0.2122},
                                           SkyCase{SkyKind::Cosine, 0, 0.1902},
                                           SkyCase{SkyKind::Uniform, 10, 0.2135},
                                           SkyCase{SkyKind::Cosine, 10, 0.1911}));

TEST(LightModel, HemisphereDefaultsToTheUniformDome) {
    EXPECT_EQ(LightSettings{}.sky, SkyKind::Uniform);
    EXPECT_EQ(kSkyNames.find("cosine"), SkyKind::Cosine);
    EXPECT_THROW(TraceSettings::fromJson({{"light", {{"sky", "overcast"}}}}), Error);
    nlohmann::json j = {{"light", {{"model", "hemisphere"}, {"sky", "cosine"}}}};
    EXPECT_EQ(TraceSettings::fromJson(j).light.sky, SkyKind::Cosine);
    EXPECT_EQ(toJson(TraceSettings::fromJson(j))["light"]["sky"], "cosine");
}

}  // namespace
