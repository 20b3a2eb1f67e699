#include "util/simd_target.h"

#include <algorithm>
#include <cctype>
#include <cstdint>

#include "hwy/highway.h"
#include "hwy/targets.h"
#include "util/error.h"

namespace facetlight {
namespace {

// Highway's target names, with AVX3 called by the ISA's usual name.
std::string nameOf(int64_t target) {
    if (target == HWY_AVX3) return "AVX-512";
    if (target == HWY_AVX3_DL) return "AVX-512-DL";
    return hwy::TargetName(target);
}

std::vector<int64_t> usable() {
    return hwy::SupportedAndGeneratedTargets();  // best (lowest bit) first
}

std::string folded(std::string_view s) {
    std::string out;
    for (char c : s) {
        if (std::isalnum(static_cast<unsigned char>(c)))
            out += char(std::toupper(static_cast<unsigned char>(c)));
    }
    return out;
}

}  // namespace

std::string simdTarget() {
    return nameOf(usable().front());
}

std::vector<std::string> simdTargets() {
    std::vector<std::string> names;
    for (int64_t t : usable()) names.push_back(nameOf(t));
    return names;
}

void limitSimdTarget(std::string_view name) {
    for (int64_t t : usable()) {
        if (folded(nameOf(t)) == folded(name) || folded(hwy::TargetName(t)) == folded(name)) {
            // Every better target has a lower bit. Highway 1.0.3's SupportedTargets() re-picks the best
            // target whenever it runs without a mock, undoing DisableTargets(): the mock is what keeps the
            // limit.
            hwy::SetSupportedTargetsForTest(hwy::SupportedTargets() & ~(t - 1));
            return;
        }
    }
    std::string known;
    for (const std::string& n : simdTargets()) known += (known.empty() ? "" : ", ") + n;
    throw Error("unknown SIMD target '" + std::string(name) + "'; this CPU runs " + known);
}

}  // namespace facetlight
