#pragma once
// Runs a test body under each SIMD target this machine runs, for the tests of the packet walks.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "hwy/targets.h"
#include "util/simd_target.h"

namespace facetlight::test {

// Runs f() once for each SIMD target compiled in that this machine supports (AVX-512, AVX2, SSE4 and the
// one-lane fallback on an AVX-512 machine), with the dispatch forced to that target.
template <class F>
void forEachSimdTarget(F&& f) {
    const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
    ASSERT_FALSE(targets.empty());  // a FACETLIGHT_NATIVE build compiles only the building machine's target
    for (const int64_t target : targets) {
        SCOPED_TRACE(hwy::TargetName(target));
        hwy::SetSupportedTargetsForTest(target);
        ASSERT_EQ(simdTargets().size(), 1u);
        f();
    }
    hwy::SetSupportedTargetsForTest(0);
}

}  // namespace facetlight::test
