// Rendered averages against analytic values (as pbrt's tests do): the mean radiance over the open floor
// around the stone, where the light arrives unshadowed and the floor is Lambertian with albedo a, is a E for
// the floor's irradiance E (the display's exposure takes the 1 / pi), which each light model gives in closed
// form.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "photonmap/photon_map.h"
#include "render/camera.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "support/fixtures.h"

namespace facetlight {
namespace {

using test::roundBrilliant;

constexpr int kSide = 96;

RenderSettings wideView() {
    RenderSettings r;
    r.width = kSide;
    r.height = kSide;
    r.samples = 4;
    r.camera.fovDeg = 40;  // the image reaches about 1.4 girdle diameters from the stone's axis
    return r;
}

// The mean of the rendered pixels, and of `expected` at the same pixels' floor points, over the ring of open
// floor 0.8 to 1.35 girdle diameters from the stone's axis: outside its shadow and its caustics, and seen
// past it. The floor points come from the camera and the floor plane, not from the renderer.
struct RegionMeans {
    Vec3 rendered;
    double expected = 0;
    int pixels = 0;
};

RegionMeans openFloorMeans(const TraceSettings& trace, const std::function<double(const Vec3&)>& expected) {
    const Scene scene(roundBrilliant(), trace);
    const RenderSettings r = wideView();
    const RenderedImage image = render(scene, PhotonMap(), r, 2, trace.seed);
    const Vec3 target = scene.toWorld(scene.center());
    const Camera camera(r.camera, target, scene.diameter(), r.width, r.height);
    double floorZ = INFINITY;
    for (const Vec3& v : roundBrilliant().vertices) floorZ = std::min(floorZ, v.z);
    RegionMeans m;
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            const Vec3 dir = camera.direction(x + 0.5, y + 0.5);
            const Vec3 p = camera.position() + dir * ((floorZ - camera.position().z) / dir.z);
            const double fromAxis = std::hypot(p.x - target.x, p.y - target.y) / scene.diameter();
            if (fromAxis < 0.8 || fromAxis > 1.35) continue;
            m.rendered += image.pixels[size_t(y) * size_t(r.width) + size_t(x)];
            m.expected += Scene::kFloorAlbedo * expected(p);
            ++m.pixels;
        }
    }
    m.rendered = m.rendered / double(m.pixels);
    m.expected /= m.pixels;
    return m;
}

// A collimated beam of unit irradiance across its direction gives the floor E = cos(theta) everywhere.
TEST(RenderedAverage, OpenFloorUnderACollimatedBeamIsAlbedoTimesCosine) {
    TraceSettings t;
    t.light.direction = normalize(Vec3{0.3, -0.2, -1});
    const double cosTheta = -t.light.direction.z;
    const RegionMeans m = openFloorMeans(t, [&](const Vec3&) { return cosTheta; });
    ASSERT_GT(m.pixels, 1000);
    for (double channel : {m.rendered.x, m.rendered.y, m.rendered.z}) EXPECT_NEAR(channel, m.expected, 1e-9);
}

// A point source of intensity I gives E = I cos(theta) / d^2; the service sets I so that E is 1 at the centre
// of the stone's bounding sphere. The floor is brightest below the source and falls off away from it, so the
// mean over the ring checks the falloff too, not a constant.
TEST(RenderedAverage, OpenFloorUnderAPointSourceFollowsTheInverseSquareLaw) {
    TraceSettings t;
    t.light.model = LightModelKind::Point;
    t.light.position = {0.4, 0.2, 3};
    const Vec3 centre = roundBrilliant().bounds.center();
    const Vec3 toCentre = centre - t.light.position;
    const double intensity = dot(toCentre, toCentre);
    const RegionMeans m = openFloorMeans(t, [&](const Vec3& p) {
        const Vec3 toLight = t.light.position - p;
        const double d2 = dot(toLight, toLight);
        return intensity * (toLight.z / std::sqrt(d2)) / d2;
    });
    ASSERT_GT(m.pixels, 1000);
    // Samples spread over each pixel while `expected` is taken at its centre: the curvature of E over a pixel
    // (1/60 of a diameter) stays far below this.
    for (double channel : {m.rendered.x, m.rendered.y, m.rendered.z})
        EXPECT_NEAR(channel / m.expected, 1, 2e-4);
}

}  // namespace
}  // namespace facetlight
