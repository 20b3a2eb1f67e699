#pragma once
// A counter-based random stream: photon i of a job with seed s draws from Rng(s, i) alone, so the result of
// a trace never depends on which thread (or which MPI rank) traced which photon. SplitMix64 (Steele, Lea &
// Flood, "Fast splittable pseudorandom number generators", OOPSLA 2014) keyed by both seed and index.
#include <cstdint>

#include "util/simd.h"

namespace facetlight {

// SplitMix64's finaliser, for a uint64_t or for lanes of them (Uint64x8 in simd.h).
template <class U>
constexpr U mix64(U z) {
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

    // The stream's position, for a packet of photons that draws from sixteen streams at once: the next
    // number is mix64(state() + kGamma).
    constexpr uint64_t state() const { return state_; }
    static constexpr uint64_t kGamma = 0x9e3779b97f4a7c15ULL;
    static constexpr uint64_t kStreamOffset = 0x632be59bd9b4e019ULL;

  private:
    uint64_t state_;
};

#if FACETLIGHT_PACKETS
// Rng's draws for lanes of streams held as their states (Rng::state()), each lane drawing what its Rng
// would. Only the lanes in `draw` advance; the others keep their state and get an unspecified number.

// Rng::next() for eight streams.
inline Uint64x8 nextOf(__m512i& state, __mmask8 draw) {
    state = _mm512_mask_add_epi64(state, draw, state, _mm512_set1_epi64(int64_t(Rng::kGamma)));
    return mix64(Uint64x8(state));
}
// Rng::uniformDouble() for eight streams.
inline __m512d uniformDoubleOf(__m512i& state, __mmask8 draw) {
    return _mm512_mul_pd(_mm512_cvtepu64_pd(_mm512_srli_epi64(nextOf(state, draw).v, 11)),
                         _mm512_set1_pd(0x1p-53));
}
// Rng::uniform() for sixteen streams, state[0..15].
inline Floats16 uniformOf(uint64_t* state, LaneMask draw) {
    __m256 half[2];
    for (int h = 0; h < 2; ++h) {
        __m512i s = _mm512_load_si512(state + 8 * h);
        half[h] = _mm512_cvtepu64_ps(_mm512_srli_epi64(nextOf(s, __mmask8(draw >> (8 * h))).v, 40));
        _mm512_store_si512(state + 8 * h, s);
    }
    return Floats16::join(half[0], half[1]) * 0x1p-24f;
}
// The states of Rng(seed, firstStream + k) for k = 0..15, into state[0..15].
inline void seedOf(uint64_t seed, uint64_t firstStream, uint64_t* state) {
    for (int h = 0; h < 2; ++h) {
        const Uint64x8 stream =
            _mm512_add_epi64(_mm512_set1_epi64(int64_t(firstStream + 8 * h + Rng::kStreamOffset)),
                             _mm512_setr_epi64(0, 1, 2, 3, 4, 5, 6, 7));
        _mm512_store_si512(state + 8 * h, mix64(Uint64x8(seed) ^ mix64(stream)).v);
    }
}
#endif

}  // namespace facetlight
