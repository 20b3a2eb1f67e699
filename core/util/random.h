#pragma once
// A counter-based random stream: photon i of a job with seed s draws from Rng(s, i) alone, so the result of
// a trace never depends on which thread (or which MPI rank) traced which photon. SplitMix64 (Steele, Lea &
// Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014) keyed by both seed and index.
#include <cstdint>

namespace facetlight {

// SplitMix64's finaliser, for a uint64_t or for lanes of them (util/lanes-inl.h; always inlined,
// so that lanes are computed with their SIMD target's instructions).
template <class U>
[[gnu::always_inline]] constexpr U mix64(U z) {
    z = (z ^ (z >> 30)) * U(0xbf58476d1ce4e5b9ULL);
    z = (z ^ (z >> 27)) * U(0x94d049bb133111ebULL);
    return z ^ (z >> 31);
}

class Rng {
  public:
    constexpr Rng(uint64_t seed, uint64_t stream) : state_(mix64(seed ^ mix64(stream + kStreamOffset))) {}

    constexpr uint64_t next() {
        state_ += kGamma;
        return mix64(state_);
    }
    // Uniform in [0, 1) with 24 bits, exactly representable as a float.
    constexpr float uniform() { return float(next() >> 40) * 0x1p-24f; }
    constexpr double uniformDouble() { return double(next() >> 11) * 0x1p-53; }
    // Passes over the next number, drawn from this stream elsewhere (a packet's lanes).
    constexpr void skip() { state_ += kGamma; }

    // The stream's position, for a packet of photons that draws from one stream per lane: the next
    // number is mix64(state() + kGamma).
    constexpr uint64_t state() const { return state_; }
    // The stream at a position state() gave: a lane's stream drawn from one photon at a time.
    static constexpr Rng resume(uint64_t state) {
        Rng r(0, 0);
        r.state_ = state;
        return r;
    }
    static constexpr uint64_t kGamma = 0x9e3779b97f4a7c15ULL;
    static constexpr uint64_t kStreamOffset = 0x632be59bd9b4e019ULL;

  private:
    uint64_t state_;
};

}  // namespace facetlight
