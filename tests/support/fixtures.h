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

// A whole trace of `stone` with `settings`, through a scene and a TraceBase made for it alone.
inline TraceResult traceStone(const Stone& stone, const TraceSettings& settings,
                              RunControl* control = nullptr) {
    const Scene scene(stone, settings);
    return trace(TraceBase(scene, settings), control);
}

}  // namespace facetlight::test
