#include "intersect/convex_intersector.h"

#include <bit>
#include <cmath>
#include <limits>

#if defined(__AVX512F__) || (defined(__AVX2__) && defined(__FMA__))
// GCC 12's AVX-512 intrinsics pass an intentionally undefined vector as the merge source, which its own
// -Wuninitialized flags (GCC bug 105593).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <immintrin.h>
#pragma GCC diagnostic pop
#endif

#include "util/error.h"

namespace facetlight {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace

ConvexIntersector::ConvexIntersector(const Stone& stone) {
    if (!stone.convex)
        throw Error("the convex intersector needs a convex stone; '" + stone.name + "' is not");
    if (stone.facets.empty()) throw Error("stone '" + stone.name + "' has no facets");
    const size_t n = stone.facets.size();
    planes_ = n;
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

#if defined(__AVX512F__)

namespace {

// 1/x to nearly full float precision: the 14-bit hardware estimate and one Newton step, much cheaper than
// a division.
inline __m512 reciprocal(__m512 x) {
    const __m512 r = _mm512_rcp14_ps(x);
    return _mm512_mul_ps(r, _mm512_fnmadd_ps(x, r, _mm512_set1_ps(2.0f)));
}

// The extreme of `t` over the lanes and the index kept in its lowest such lane.
template <bool kMin>
inline SurfaceHit reduce(__m512 t, __m512i idx) {
    const float m = kMin ? _mm512_reduce_min_ps(t) : _mm512_reduce_max_ps(t);
    const __mmask16 at = _mm512_cmp_ps_mask(t, _mm512_set1_ps(m), _CMP_EQ_OQ);
    alignas(64) uint32_t lanes[16];
    _mm512_store_si512(lanes, idx);
    return {m, lanes[at ? __builtin_ctz(unsigned(at)) : 0]};
}

struct Ray16 {
    __m512 ox, oy, oz, dx, dy, dz;
    Ray16(const Vec3f& o, const Vec3f& d)
        : ox(_mm512_set1_ps(o.x)),
          oy(_mm512_set1_ps(o.y)),
          oz(_mm512_set1_ps(o.z)),
          dx(_mm512_set1_ps(d.x)),
          dy(_mm512_set1_ps(d.y)),
          dz(_mm512_set1_ps(d.z)) {}
};

struct PlaneTerms {
    __m512 den;  // dot(dir, n): > 0 where the ray heads out through the plane
    __m512 num;  // offset - dot(origin, n): the ray meets the plane at t = num / den
};

inline PlaneTerms terms(const float* nx, const float* ny, const float* nz, const float* offset,
                        const Ray16& r) {
    const __m512 x = _mm512_loadu_ps(nx), y = _mm512_loadu_ps(ny), z = _mm512_loadu_ps(nz);
    return {_mm512_fmadd_ps(r.dx, x, _mm512_fmadd_ps(r.dy, y, _mm512_mul_ps(r.dz, z))),
            _mm512_sub_ps(_mm512_loadu_ps(offset),
                          _mm512_fmadd_ps(r.ox, x, _mm512_fmadd_ps(r.oy, y, _mm512_mul_ps(r.oz, z))))};
}

const __m512i kLaneIndex = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);

}  // namespace

bool ConvexIntersector::leave(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    const Ray16 r(o, d);
    const __m512 zero = _mm512_setzero_ps();
    __m512 best = _mm512_set1_ps(kInf);
    __m512i bestIdx = _mm512_setzero_si512(), idx = kLaneIndex;
    const __m512i step = _mm512_set1_epi32(16);
    for (size_t i = 0; i < padded_; i += kWidth) {
        const PlaneTerms p = terms(&nx_[i], &ny_[i], &nz_[i], &offset_[i], r);
        const __mmask16 out = _mm512_cmp_ps_mask(p.den, zero, _CMP_GT_OQ);
        // A point a rounding error outside a plane it heads out through leaves at once, at t = 0.
        const __m512 t = _mm512_max_ps(_mm512_mul_ps(p.num, reciprocal(p.den)), zero);
        const __mmask16 better = _mm512_mask_cmp_ps_mask(out, t, best, _CMP_LT_OQ);
        best = _mm512_mask_mov_ps(best, better, t);
        bestIdx = _mm512_mask_mov_epi32(bestIdx, better, idx);
        idx = _mm512_add_epi32(idx, step);
    }
    // Non-negative floats order as their bit patterns, so one 64-bit key (t above, plane below) per lane
    // gives the nearest plane and, on ties, the lowest one in a single integer reduction.
    const __m512i keys = _mm512_min_epu64(_mm512_unpacklo_epi32(bestIdx, _mm512_castps_si512(best)),
                                          _mm512_unpackhi_epi32(bestIdx, _mm512_castps_si512(best)));
    const uint64_t key = _mm512_reduce_min_epu64(keys);
    hit = {std::bit_cast<float>(uint32_t(key >> 32)), uint32_t(key)};
    return hit.t < kInf;
}

#if FACETLIGHT_PACKETS
void ConvexIntersector::leave(const RayPacket& rays, Floats16& tOut, __m512i& facetOut) const {
    // The plane loop of leave(const Vec3f&, ...) turned around: one plane against sixteen rays, with the
    // same operations per (ray, plane), so each lane's t has the same bits. Two interleaved searches over
    // even and odd planes halve the chain of dependent compares.
    const __m512 zero = _mm512_setzero_ps(), inf = _mm512_set1_ps(kInf);
    __m512 best[2] = {inf, inf};
    __m512i bestIdx[2] = {_mm512_setzero_si512(), _mm512_setzero_si512()};
    auto visit = [&](size_t i, int chain) {
        const __m512 x = _mm512_set1_ps(nx_[i]), y = _mm512_set1_ps(ny_[i]), z = _mm512_set1_ps(nz_[i]);
        const __m512 den =
            _mm512_fmadd_ps(rays.dx.v, x, _mm512_fmadd_ps(rays.dy.v, y, _mm512_mul_ps(rays.dz.v, z)));
        const __m512 num = _mm512_sub_ps(
            _mm512_set1_ps(offset_[i]),
            _mm512_fmadd_ps(rays.ox.v, x, _mm512_fmadd_ps(rays.oy.v, y, _mm512_mul_ps(rays.oz.v, z))));
        const __mmask16 out = _mm512_cmp_ps_mask(den, zero, _CMP_GT_OQ);
        const __m512 t = _mm512_max_ps(_mm512_mul_ps(num, reciprocal(den)), zero);
        const __mmask16 better = _mm512_mask_cmp_ps_mask(out, t, best[chain], _CMP_LT_OQ);
        best[chain] = _mm512_mask_mov_ps(best[chain], better, t);
        bestIdx[chain] = _mm512_mask_mov_epi32(bestIdx[chain], better, _mm512_set1_epi32(int(i)));
    };
    size_t i = 0;
    for (; i + 1 < planes_; i += 2) {
        visit(i, 0);
        visit(i + 1, 1);
    }
    if (i < planes_) visit(i, 0);
    // The nearer of the two, and on a tie the lower plane, as the one-ray search picks.
    const __mmask16 odd =
        _mm512_cmp_ps_mask(best[1], best[0], _CMP_LT_OQ) |
        (_mm512_cmp_ps_mask(best[1], best[0], _CMP_EQ_OQ) & _mm512_cmplt_epu32_mask(bestIdx[1], bestIdx[0]));
    tOut = _mm512_mask_mov_ps(best[0], odd, best[1]);
    facetOut = _mm512_mask_mov_epi32(bestIdx[0], odd, bestIdx[1]);
}
#endif

bool ConvexIntersector::enter(const Vec3f& o, const Vec3f& d, SurfaceHit& hit) const {
    const Ray16 r(o, d);
    const __m512 zero = _mm512_setzero_ps();
    __m512 tIn = _mm512_set1_ps(-kInf), tOut = _mm512_set1_ps(kInf);
    __mmask16 outside = 0;
    __m512i inIdx = _mm512_setzero_si512(), idx = kLaneIndex;
    const __m512i step = _mm512_set1_epi32(16);
    for (size_t i = 0; i < padded_; i += kWidth) {
        const PlaneTerms p = terms(&nx_[i], &ny_[i], &nz_[i], &offset_[i], r);
        const __m512 t = _mm512_mul_ps(p.num, reciprocal(p.den));
        tOut = _mm512_mask_min_ps(tOut, _mm512_cmp_ps_mask(p.den, zero, _CMP_GT_OQ), tOut, t);
        const __mmask16 inward = _mm512_cmp_ps_mask(p.den, zero, _CMP_LT_OQ);
        const __mmask16 better = _mm512_mask_cmp_ps_mask(inward, t, tIn, _CMP_GT_OQ);
        tIn = _mm512_mask_mov_ps(tIn, better, t);
        inIdx = _mm512_mask_mov_epi32(inIdx, better, idx);
        // A ray parallel to a plane it is outside of never enters.
        outside |=
            _mm512_mask_cmp_ps_mask(_mm512_cmp_ps_mask(p.den, zero, _CMP_EQ_OQ), p.num, zero, _CMP_LT_OQ);
        idx = _mm512_add_epi32(idx, step);
    }
    hit = reduce<false>(tIn, inIdx);
    return hit.t > 0 && hit.t <= _mm512_reduce_min_ps(tOut) && outside == 0;
}

#elif defined(__AVX2__) && defined(__FMA__)

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

void ConvexBeamEntry::Planes::add(float a_, const Vec3f& m, uint32_t f) {
    a.push_back(a_);
    mx.push_back(m.x);
    my.push_back(m.y);
    mz.push_back(m.z);
    facet.push_back(f);
}

void ConvexBeamEntry::Planes::pad(float a_) {
    while (a.empty() || a.size() % ConvexIntersector::kWidth) add(a_, {}, 0);
}

ConvexBeamEntry::ConvexBeamEntry(const Stone& stone, const Vec3f& dir) {
    if (!stone.convex)
        throw Error("the convex intersector needs a convex stone; '" + stone.name + "' is not");
    for (size_t i = 0; i < stone.facets.size(); ++i) {
        const Facet& f = stone.facets[i];
        const Vec3f n(f.normal);
        const float den = dot(dir, n), offset = float(f.offset);
        if (den == 0) {
            parallelNormal_.push_back(n);
            parallelOffset_.push_back(offset);
        } else {
            (den < 0 ? in_ : out_).add(offset / den, n * (1 / den), uint32_t(i));
        }
    }
    const size_t entering = in_.a.size();
    in_.pad(-kInf);
    out_.pad(kInf);
    for (size_t lane = 0; lane < ConvexIntersector::kWidth; ++lane) {
        for (size_t i = lane; i < entering; i += ConvexIntersector::kWidth)
            inTieOrder_.push_back(uint32_t(i));
    }
}

#if defined(__AVX512F__)

bool ConvexBeamEntry::enter(const Vec3f& o, SurfaceHit& hit) const {
    const __m512 ox = _mm512_set1_ps(o.x), oy = _mm512_set1_ps(o.y), oz = _mm512_set1_ps(o.z);
    auto t = [&](const Planes& p, size_t i) {
        return _mm512_sub_ps(_mm512_loadu_ps(&p.a[i]),
                             _mm512_fmadd_ps(ox, _mm512_loadu_ps(&p.mx[i]),
                                             _mm512_fmadd_ps(oy, _mm512_loadu_ps(&p.my[i]),
                                                             _mm512_mul_ps(oz, _mm512_loadu_ps(&p.mz[i])))));
    };
    __m512 tIn = _mm512_set1_ps(-kInf);
    __m512i inIdx = _mm512_setzero_si512();
    for (size_t i = 0; i < in_.a.size(); i += ConvexIntersector::kWidth) {
        const __m512 ti = t(in_, i);
        const __mmask16 better = _mm512_cmp_ps_mask(ti, tIn, _CMP_GT_OQ);
        tIn = _mm512_mask_mov_ps(tIn, better, ti);
        inIdx = _mm512_mask_loadu_epi32(inIdx, better, &in_.facet[i]);
    }
    __m512 tOut = _mm512_set1_ps(kInf);
    for (size_t i = 0; i < out_.a.size(); i += ConvexIntersector::kWidth)
        tOut = _mm512_min_ps(tOut, t(out_, i));
    hit = reduce<false>(tIn, inIdx);
    if (!(hit.t > 0) || _mm512_cmp_ps_mask(tOut, _mm512_set1_ps(hit.t), _CMP_LT_OQ)) return false;
    for (size_t i = 0; i < parallelOffset_.size(); ++i) {
        if (dot(o, parallelNormal_[i]) > parallelOffset_[i]) return false;
    }
    return true;
}

#if FACETLIGHT_PACKETS
LaneMask ConvexBeamEntry::enter(const Floats16& ox, const Floats16& oy, const Floats16& oz, Floats16& tOut,
                                __m512i& facetOut) const {
    // The same operations per (origin, plane) as the one-origin search; the entry planes in the order that
    // search settles ties in, so that each lane gets its facet too.
    auto t = [&](const Planes& p, size_t i) {
        return _mm512_sub_ps(_mm512_set1_ps(p.a[i]),
                             _mm512_fmadd_ps(ox.v, _mm512_set1_ps(p.mx[i]),
                                             _mm512_fmadd_ps(oy.v, _mm512_set1_ps(p.my[i]),
                                                             _mm512_mul_ps(oz.v, _mm512_set1_ps(p.mz[i])))));
    };
    __m512 tIn = _mm512_set1_ps(-kInf);
    __m512i inIdx = _mm512_setzero_si512();
    for (const uint32_t i : inTieOrder_) {
        const __m512 ti = t(in_, i);
        const __mmask16 better = _mm512_cmp_ps_mask(ti, tIn, _CMP_GT_OQ);
        tIn = _mm512_mask_mov_ps(tIn, better, ti);
        inIdx = _mm512_mask_mov_epi32(inIdx, better, _mm512_set1_epi32(int(in_.facet[i])));
    }
    __m512 tExit = _mm512_set1_ps(kInf);
    for (size_t i = 0; i < out_.a.size(); ++i) tExit = _mm512_min_ps(tExit, t(out_, i));
    __mmask16 enters = _mm512_mask_cmp_ps_mask(_mm512_cmp_ps_mask(tIn, _mm512_setzero_ps(), _CMP_GT_OQ),
                                               tExit, tIn, _CMP_NLT_UQ);
    for (size_t i = 0; i < parallelOffset_.size(); ++i) {
        const Vec3f& n = parallelNormal_[i];
        const Floats16 side = ox * Floats16(n.x) + oy * Floats16(n.y) + oz * Floats16(n.z);
        enters &= __mmask16(~(Floats16(parallelOffset_[i]) < side));
    }
    tOut = tIn;
    facetOut = inIdx;
    return enters;
}
#endif

#else

bool ConvexBeamEntry::enter(const Vec3f& o, SurfaceHit& hit) const {
    hit = {-kInf, 0};
    float exitT = kInf;
    for (size_t i = 0; i < in_.a.size(); ++i) {
        const float t = in_.a[i] - (o.x * in_.mx[i] + o.y * in_.my[i] + o.z * in_.mz[i]);
        if (t > hit.t) hit = {t, in_.facet[i]};
    }
    for (size_t i = 0; i < out_.a.size(); ++i)
        exitT = std::fmin(exitT, out_.a[i] - (o.x * out_.mx[i] + o.y * out_.my[i] + o.z * out_.mz[i]));
    if (!(hit.t > 0 && hit.t <= exitT)) return false;
    for (size_t i = 0; i < parallelOffset_.size(); ++i) {
        if (dot(o, parallelNormal_[i]) > parallelOffset_[i]) return false;
    }
    return true;
}

#endif

}  // namespace facetlight
