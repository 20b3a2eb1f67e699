#pragma once
// Fixtures shared by the test folders: stones built once per test binary, a whole trace of a stone.
#include "cuts/mesh_resolver.h"
#include "scene/scene.h"
#include "stone/stone.h"
#include "trace/photon_tracer.h"

namespace facetlight::test {

// The cut library's default round brilliant, built once.
inline const Stone& roundBrilliant() {
    static const Stone stone = resolveStone("round_brilliant");
    return stone;
}

// A hexahedron with named faces (bottom, top, front, back, left, right) whose corner i is corner(i), the bits
// of i saying which end of x, y and z it is at: a box, or a box with a slanted top.
template <class Corner>
Stone hexahedron(Corner corner, const char* name) {
    PolygonMesh m;
    for (int i = 0; i < 8; ++i) m.vertices.push_back(corner(i));
    m.polygons = {{{0, 2, 3, 1}, "bottom"}, {{4, 5, 7, 6}, "top"},  {{0, 1, 5, 4}, "front"},
                  {{2, 6, 7, 3}, "back"},   {{0, 4, 6, 2}, "left"}, {{1, 3, 7, 5}, "right"}};
    return Stone::build(m, name);
}

// An axis-aligned box from the origin to (sx, sy, sz) (Stone::build centres it on the origin).
inline Stone box(double sx, double sy, double sz) {
    return hexahedron(
        [&](int i) {
            return Vec3{sx * (i & 1), sy * ((i >> 1) & 1), sz * ((i >> 2) & 1)};
        },
        "box");
}

// The unit cube [0, 1]^3 with named faces: a slab for analytic tests.
inline Stone unitCube() {
    return hexahedron(
        [](int i) {
            return Vec3{double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)};
        },
        "cube");
}

// A whole trace of `stone` with `settings`, through a scene and a TraceBase made for it alone.
inline TraceResult traceStone(const Stone& stone, const TraceSettings& settings,
                              RunControl* control = nullptr) {
    const Scene scene(stone, settings);
    return trace(TraceBase(scene, settings), control);
}

}  // namespace facetlight::test
