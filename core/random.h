#pragma once
// A counter-based random stream: photon i of a job with seed s draws from Rng(s, i) alone, so the result of
// a trace never depends on which thread (or which MPI rank) traced which photon. SplitMix64 (Steele, Lea &
// Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014) keyed by both seed and index.
#include <cstdint>

namespace facetlight {

constexpr uint64_t mix64(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

class Rng {
  public:
    constexpr Rng(uint64_t seed, uint64_t stream)
        : state_(mix64(seed ^ mix64(stream + 0x632be59bd9b4e019ULL))) {}

    constexpr uint64_t next() {
        state_ += 0x9e3779b97f4a7c15ULL;
        return mix64(state_);
    }
    // Uniform in [0, 1) with 24 bits, exactly representable as a float.
    constexpr float uniform() { return float(next() >> 40) * 0x1p-24f; }
    constexpr double uniformDouble() { return double(next() >> 11) * 0x1p-53; }

  private:
    uint64_t state_;
};

}  // namespace facetlight
