#include "convex_intersector.h"

#include <cmath>
#include <limits>

#if defined(__AVX2__) && defined(__FMA__)
#include <immintrin.h>
#endif

#include "error.h"

namespace facetlight {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace

ConvexIntersector::ConvexIntersector(const Stone& stone) {
    if (!stone.convex)
        throw Error("the convex intersector needs a convex stone; '" + stone.name + "' is not");
    if (stone.facets.empty()) throw Error("stone '" + stone.name + "' has no facets");
    const size_t n = stone.facets.size();
    padded_ = (n + kWidth - 1) / kWidth * kWidth;
    nx_.assign(padded_, 0.0f);
    ny_.assign(padded_, 0.0f);
    nz_.assign(padded_, 0.0f);
    offset_.assign(padded_, 1.0f);
    for (size_t i = 0; i < n; ++i) {
        const Facet& f = stone.facets[i];
        nx_[i] = float(f.normal.x);
        ny_[i] = float(f.normal.y);
        nz_[i] = float(f.normal.z);
        offset_[i] = float(f.offset);
    }
}

#if defined(__AVX2__) && defined(__FMA__)

namespace {

// 1/x to nearly full float precision: the hardware estimate and one Newton step, much cheaper than a
// division.
inline __m256 reciprocal(__m256 x) {
    const __m256 r = _mm256_rcp_ps(x);
    return _mm256_mul_ps(r, _mm256_fnmadd_ps(x, r, _mm256_set1_ps(2.0f)));
}

// The lane holding the extreme of `t` (the lowest such lane on ties) and the plane index kept in that lane.
template <bool kMin>
inline SurfaceHit reduce(__m256 t, __m256i idx) {
    auto pick = [](__m256 a, __m256 b) { return kMin ? _mm256_min_ps(a, b) : _mm256_max_ps(a, b); };
    __m256 m = pick(t, _mm256_permute2f128_ps(t, t, 1));
    m = pick(m, _mm256_permute_ps(m, _MM_SHUFFLE(1, 0, 3, 2)));
    m = pick(m, _mm256_permute_ps(m, _MM_SHUFFLE(2, 3, 0, 1)));
    const int mask = _mm256_movemask_ps(_mm256_cmp_ps(t, m, _CMP_EQ_OQ));
    alignas(32) uint32_t lanes[8];
    _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), idx);
    return {_mm256_cvtss_f32(m), lanes[mask ? __builtin_ctz(unsigned(mask)) : 0]};
}

struct PlaneTerms {
    __m256 den;  // dot(dir, n): > 0 where the ray heads out through the plane
    __m256 num;  // offset - dot(origin, n): the ray meets the plane at t = num / den
};

inline PlaneTerms terms(const float* nx, const float* ny, const float* nz, const float* offset, __m256 ox,
                        __m256 oy, __m256 oz, __m256 dx, __m256 dy, __m256 dz) {
    const __m256 x = _mm256_loadu_ps(nx), y = _mm256_loadu_ps(ny), z = _mm256_loadu_ps(nz);
    return {_mm256_fmadd_ps(dx, x, _mm256_fmadd_ps(dy, y, _mm256_mul_ps(dz, z))),
            _mm256_sub_ps(_mm256_loadu_ps(offset),
                          _mm256_fmadd_ps(ox, x, _mm256_fmadd_ps(oy, y, _mm256_mul_ps(oz, z))))};
}

}  // namespace

bool ConvexIntersector::leave(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    const __m256 ox = _mm256_set1_ps(o.x), oy = _mm256_set1_ps(o.y), oz = _mm256_set1_ps(o.z);
    const __m256 dx = _mm256_set1_ps(d.x), dy = _mm256_set1_ps(d.y), dz = _mm256_set1_ps(d.z);
    const __m256 zero = _mm256_setzero_ps(), inf = _mm256_set1_ps(kInf);
    __m256 best = inf;
    __m256i bestIdx = _mm256_setzero_si256(), idx = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i step = _mm256_set1_epi32(8);
    for (size_t i = 0; i < padded_; i += kWidth) {
        const PlaneTerms p = terms(&nx_[i], &ny_[i], &nz_[i], &offset_[i], ox, oy, oz, dx, dy, dz);
        const __m256 t = _mm256_blendv_ps(inf, _mm256_mul_ps(p.num, reciprocal(p.den)),
                                          _mm256_cmp_ps(p.den, zero, _CMP_GT_OQ));
        const __m256 better = _mm256_cmp_ps(t, best, _CMP_LT_OQ);
        best = _mm256_blendv_ps(best, t, better);
        bestIdx = _mm256_castps_si256(
            _mm256_blendv_ps(_mm256_castsi256_ps(bestIdx), _mm256_castsi256_ps(idx), better));
        idx = _mm256_add_epi32(idx, step);
    }
    hit = reduce<true>(best, bestIdx);
    hit.t = hit.t > 0 ? hit.t : 0.0f;
    return hit.t < kInf;
}

bool ConvexIntersector::enter(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    const __m256 ox = _mm256_set1_ps(o.x), oy = _mm256_set1_ps(o.y), oz = _mm256_set1_ps(o.z);
    const __m256 dx = _mm256_set1_ps(d.x), dy = _mm256_set1_ps(d.y), dz = _mm256_set1_ps(d.z);
    const __m256 zero = _mm256_setzero_ps(), inf = _mm256_set1_ps(kInf), ninf = _mm256_set1_ps(-kInf);
    __m256 tIn = ninf, tOut = inf, outside = zero;
    __m256i inIdx = _mm256_setzero_si256(), idx = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    const __m256i step = _mm256_set1_epi32(8);
    for (size_t i = 0; i < padded_; i += kWidth) {
        const PlaneTerms p = terms(&nx_[i], &ny_[i], &nz_[i], &offset_[i], ox, oy, oz, dx, dy, dz);
        const __m256 t = _mm256_mul_ps(p.num, reciprocal(p.den));
        tOut = _mm256_min_ps(tOut, _mm256_blendv_ps(inf, t, _mm256_cmp_ps(p.den, zero, _CMP_GT_OQ)));
        const __m256 entering = _mm256_blendv_ps(ninf, t, _mm256_cmp_ps(p.den, zero, _CMP_LT_OQ));
        const __m256 better = _mm256_cmp_ps(entering, tIn, _CMP_GT_OQ);
        tIn = _mm256_blendv_ps(tIn, entering, better);
        inIdx = _mm256_castps_si256(
            _mm256_blendv_ps(_mm256_castsi256_ps(inIdx), _mm256_castsi256_ps(idx), better));
        // A ray parallel to a plane it is outside of never enters.
        outside = _mm256_or_ps(outside, _mm256_and_ps(_mm256_cmp_ps(p.den, zero, _CMP_EQ_OQ),
                                                      _mm256_cmp_ps(p.num, zero, _CMP_LT_OQ)));
        idx = _mm256_add_epi32(idx, step);
    }
    hit = reduce<false>(tIn, inIdx);
    const float exitT = reduce<true>(tOut, inIdx).t;
    return hit.t > 0 && hit.t <= exitT && _mm256_movemask_ps(outside) == 0;
}

#else  // portable fallback with the same semantics

bool ConvexIntersector::leave(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    hit = {kInf, 0};
    for (size_t i = 0; i < padded_; ++i) {
        const float den = d.x * nx_[i] + d.y * ny_[i] + d.z * nz_[i];
        const float t = den > 0 ? (offset_[i] - (o.x * nx_[i] + o.y * ny_[i] + o.z * nz_[i])) / den : kInf;
        if (t < hit.t) hit = {t, uint32_t(i)};
    }
    hit.t = hit.t > 0 ? hit.t : 0.0f;
    return hit.t < kInf;
}

bool ConvexIntersector::enter(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    hit = {-kInf, 0};
    float exitT = kInf;
    for (size_t i = 0; i < padded_; ++i) {
        const float den = d.x * nx_[i] + d.y * ny_[i] + d.z * nz_[i];
        const float t = (offset_[i] - (o.x * nx_[i] + o.y * ny_[i] + o.z * nz_[i])) / den;
        if (den > 0) exitT = std::fmin(exitT, t);
        if (den == 0 && offset_[i] < o.x * nx_[i] + o.y * ny_[i] + o.z * nz_[i]) return false;
        if (den < 0 && t > hit.t) hit = {t, uint32_t(i)};
    }
    return hit.t > 0 && hit.t <= exitT;
}

#endif

}  // namespace facetlight
