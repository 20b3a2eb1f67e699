#pragma once
// Fixtures shared by the test folders: stones built once per test binary.
#include "cuts/mesh_resolver.h"
#include "stone/stone.h"

namespace facetlight::test {

// The cut library's default round brilliant, built once.
inline const Stone& roundBrilliant() {
    static const Stone stone = resolveStone("round_brilliant");
    return stone;
}

}  // namespace facetlight::test
