#pragma once
// Sixteen float lanes (and eight double or 64-bit integer lanes) with the operators of their scalar types, so
// that one template, such as fresnelTerms or mix64, computes the same bits for a single photon and for a
// packet of sixteen. Each operator is one correctly rounded instruction, as the scalar operator is when the
// compiler does not contract a * b + c into an FMA (core/ is built with -ffp-contract=off).
#if defined(__AVX512F__) && defined(__AVX512DQ__)
#define FACETLIGHT_PACKETS 1

#include <cstdint>

// GCC 12's AVX-512 intrinsics pass an intentionally undefined vector as the merge source, which its own
// -Wuninitialized flags (GCC bug 105593).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop

namespace facetlight {

using LaneMask = __mmask16;

struct Floats16 {
    __m512 v;
    Floats16() = default;
    Floats16(__m512 x) : v(x) {}
    explicit Floats16(float s) : v(_mm512_set1_ps(s)) {}
    static Floats16 load(const float* p) { return _mm512_load_ps(p); }
    // Lanes 0-7 from lo and 8-15 from hi.
    static Floats16 join(__m256 lo, __m256 hi) {
        return _mm512_insertf32x8(_mm512_castps256_ps512(lo), hi, 1);
    }
    void store(float* p) const { _mm512_store_ps(p, v); }
};

inline Floats16 operator+(Floats16 a, Floats16 b) {
    return _mm512_add_ps(a.v, b.v);
}
inline Floats16 operator-(Floats16 a, Floats16 b) {
    return _mm512_sub_ps(a.v, b.v);
}
inline Floats16 operator*(Floats16 a, Floats16 b) {
    return _mm512_mul_ps(a.v, b.v);
}
inline Floats16 operator/(Floats16 a, Floats16 b) {
    return _mm512_div_ps(a.v, b.v);
}
inline Floats16 operator-(Floats16 a) {
    return _mm512_xor_ps(a.v, _mm512_set1_ps(-0.0f));  // the sign flipped, as scalar negation does
}
inline Floats16 operator*(Floats16 a, float s) {
    return a * Floats16(s);
}
inline Floats16 operator*(float s, Floats16 a) {
    return Floats16(s) * a;
}
inline Floats16 operator-(float s, Floats16 a) {
    return Floats16(s) - a;
}
// Ordered comparisons, false where either side is NaN, as for scalar floats.
inline LaneMask operator<(Floats16 a, Floats16 b) {
    return _mm512_cmp_ps_mask(a.v, b.v, _CMP_LT_OQ);
}
inline LaneMask operator>=(Floats16 a, Floats16 b) {
    return _mm512_cmp_ps_mask(a.v, b.v, _CMP_GE_OQ);
}
inline Floats16 sqrt(Floats16 a) {
    return _mm512_sqrt_ps(a.v);
}
// a where the mask is set, else b: the lane-wise `mask ? a : b`.
inline Floats16 select(LaneMask mask, Floats16 a, Floats16 b) {
    return _mm512_mask_blend_ps(mask, b.v, a.v);
}

struct Doubles8 {
    __m512d v;
    Doubles8() = default;
    Doubles8(__m512d x) : v(x) {}
    explicit Doubles8(double s) : v(_mm512_set1_pd(s)) {}
};

inline Doubles8 operator+(Doubles8 a, Doubles8 b) {
    return _mm512_add_pd(a.v, b.v);
}
inline Doubles8 operator-(Doubles8 a, Doubles8 b) {
    return _mm512_sub_pd(a.v, b.v);
}
inline Doubles8 operator*(Doubles8 a, Doubles8 b) {
    return _mm512_mul_pd(a.v, b.v);
}
inline Doubles8 operator/(Doubles8 a, Doubles8 b) {
    return _mm512_div_pd(a.v, b.v);
}
inline Doubles8 sqrt(Doubles8 a) {
    return _mm512_sqrt_pd(a.v);
}

// A function of doubles applied to sixteen floats, in two halves of eight: f(double(x)) rounded to float.
template <class F>
inline Floats16 viaDoubles(Floats16 x, F&& f) {
    const Doubles8 lo = _mm512_cvtps_pd(_mm512_castps512_ps256(x.v));
    const Doubles8 hi = _mm512_cvtps_pd(_mm512_extractf32x8_ps(x.v, 1));
    return Floats16::join(_mm512_cvtpd_ps(f(lo).v), _mm512_cvtpd_ps(f(hi).v));
}

struct Uint64x8 {
    __m512i v;
    Uint64x8() = default;
    Uint64x8(__m512i x) : v(x) {}
    constexpr explicit Uint64x8(uint64_t s) : v(__m512i(__v8du{s, s, s, s, s, s, s, s})) {}
};

inline Uint64x8 operator^(Uint64x8 a, Uint64x8 b) {
    return _mm512_xor_si512(a.v, b.v);
}
inline Uint64x8 operator>>(Uint64x8 a, unsigned shift) {
    return _mm512_srli_epi64(a.v, shift);
}
inline Uint64x8 operator*(Uint64x8 a, Uint64x8 b) {
    return _mm512_mullo_epi64(a.v, b.v);
}

}  // namespace facetlight

#endif
