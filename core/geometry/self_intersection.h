#pragma once
// Whether a closed triangle mesh passes through itself. A stone whose surface crosses itself has no inside
// and outside, so no tally of where light leaves it means anything.
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "geometry/geometry.h"

namespace facetlight {

using TriangleIndices = std::array<uint32_t, 3>;

// Two triangles that share more than their common vertices and edges, by more than `eps`: an edge of one
// passes through the other, or, lying in one plane, they overlap (a surface folded onto itself). Candidate
// pairs come from a uniform grid of the triangles' boxes. Throws Error when the boxes overlap so much that
// the check would take more than a few hundred pair tests per triangle (no real stone comes close).
std::optional<std::pair<uint32_t, uint32_t>> findCrossingTriangles(const std::vector<Vec3>& vertices,
                                                                   const std::vector<TriangleIndices>& triangles,
                                                                   double eps);

}  // namespace facetlight
