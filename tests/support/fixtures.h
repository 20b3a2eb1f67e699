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

// The unit cube [0, 1]^3 with named faces (Stone::build centres it on the origin): a slab for analytic tests.
inline Stone unitCube() {
    PolygonMesh m;
    for (int i = 0; i < 8; ++i)
        m.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    m.polygons = {{{0, 2, 3, 1}, "bottom"}, {{4, 5, 7, 6}, "top"},  {{0, 1, 5, 4}, "front"},
                  {{2, 6, 7, 3}, "back"},   {{0, 4, 6, 2}, "left"}, {{1, 3, 7, 5}, "right"}};
    return Stone::build(m, "cube");
}

// A whole trace of `stone` with `settings`, through a scene and a TraceBase made for it alone.
inline TraceResult traceStone(const Stone& stone, const TraceSettings& settings,
                              RunControl* control = nullptr) {
    const Scene scene(stone, settings);
    return trace(TraceBase(scene, settings), control);
}

}  // namespace facetlight::test
