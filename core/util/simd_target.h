#pragma once
// The SIMD target the photon walk and the convex intersectors run on: the best of those compiled in (SSE4,
// AVX2, AVX-512, and Highway's one-lane fallback, SCALAR with GCC before 12.3 and EMU128 after) that the CPU
// supports, picked at run time.
// Every target computes the same bits (docs/performance.md, "Portable speed").
#include <string>
#include <string_view>
#include <vector>

namespace facetlight {

// The target in use, e.g. "AVX2" or "AVX-512".
std::string simdTarget();
// The targets compiled in that this CPU supports, best first.
std::vector<std::string> simdTargets();
// Uses `name` (one of simdTargets(), any case) or the best below it from then on, e.g. to measure AVX2 on an
// AVX-512 machine. Affects intersectors and scenes built afterwards. Throws Error for any other name.
void limitSimdTarget(std::string_view name);

}  // namespace facetlight
