// Inside core/ (per SIMD target): the searches of ConvexIntersector and ConvexBeamEntry, for one ray against
// the planes in lanes (the renderer, tracePhoton) and for a packet of rays, one per lane, against one plane
// at a time (the packet walk). Every (ray, plane) pair takes the same operations in the same order in both,
// on every target, and the extreme t goes to the lowest facet on ties, so each ray gets the same bits
// whichever search and target traces it.
#if defined(FACETLIGHT_CONVEX_SEARCH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef FACETLIGHT_CONVEX_SEARCH_INL_H_
#undef FACETLIGHT_CONVEX_SEARCH_INL_H_
#else
#define FACETLIGHT_CONVEX_SEARCH_INL_H_
#endif

#include <cstdint>
#include <limits>

#include "hwy/highway.h"
#include "intersect/convex_intersector.h"
#include "util/lanes-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {

constexpr float kInf = std::numeric_limits<float>::infinity();

// dot(a, b) as Vec3f's dot rounds it: (ax bx + ay by) + az bz.
template <class F>
HWY_INLINE F dot3(F ax, F ay, F az, F bx, F by, F bz) {
    return ax * bx + ay * by + az * bz;
}

// Where a ray meets plane (n, offset): den = dot(dir, n), > 0 where it heads out through the plane, and
// num = offset - dot(origin, n); they meet at t = num / den.
template <class F>
struct PlaneCrossing {
    F den, num;
    HWY_INLINE PlaneCrossing(F ox, F oy, F oz, F dx, F dy, F dz, F nx, F ny, F nz, F offset)
        : den(dot3(dx, dy, dz, nx, ny, nz)), num(offset - dot3(ox, oy, oz, nx, ny, nz)) {}
};

// The distance to leave through an outward plane: num / den, and 0 for a point a rounding error outside it.
template <class F>
HWY_INLINE F leavingT(const PlaneCrossing<F>& c) {
    const F zero(0.0f), t = c.num / c.den;
    return select(zero < t, t, zero);
}

// ---- One ray, the planes in lanes.

using PlaneTag = hn::CappedTag<float, ConvexIntersector::Planes::kPadding>;
using PlaneLanes = Lanes<PlaneTag>;
using PlaneIndexTag = hn::RebindToSigned<PlaneTag>;

// The facet of the lowest index among the lanes whose t equals the extreme `best` (broadcast).
HWY_INLINE uint32_t lowestFacetAt(PlaneLanes t, hn::Vec<PlaneTag> best, hn::Vec<PlaneIndexTag> facet) {
    const PlaneIndexTag di;
    const auto at = hn::RebindMask(di, hn::Eq(t.v, best));
    return uint32_t(hn::GetLane(hn::MinOfLanes(di, hn::IfThenElse(at, facet, hn::Set(di, INT32_MAX)))));
}

// The ray's crossings of planes [i, i + lanes).
HWY_INLINE PlaneCrossing<PlaneLanes> crossings(const ConvexIntersector::Planes& p, size_t i, PlaneLanes ox,
                                               PlaneLanes oy, PlaneLanes oz, PlaneLanes dx, PlaneLanes dy,
                                               PlaneLanes dz) {
    return {ox,
            oy,
            oz,
            dx,
            dy,
            dz,
            PlaneLanes::load(&p.nx[i]),
            PlaneLanes::load(&p.ny[i]),
            PlaneLanes::load(&p.nz[i]),
            PlaneLanes::load(&p.offset[i])};
}

// The planes' facets, [i, i + lanes).
HWY_INLINE hn::Vec<PlaneIndexTag> facetsAt(const ConvexIntersector::Planes& p, size_t i) {
    return hn::BitCast(PlaneIndexTag(), hn::LoadU(hn::RebindToUnsigned<PlaneTag>(), &p.facet[i]));
}

// The nearest exit through the planes of `p`, the lowest facet on ties; t = +inf where there is none.
HWY_INLINE void LeaveRay(const ConvexIntersector::Planes& p, const Vec3f& o, const Vec3f& d,
                         SurfaceHit& hit) {
    const PlaneTag df;
    const PlaneIndexTag di;
    const PlaneLanes ox(o.x), oy(o.y), oz(o.z), dx(d.x), dy(d.y), dz(d.z), zero(0.0f);
    PlaneLanes best(kInf);
    auto bestFacet = hn::Zero(di);
    for (size_t i = 0; i < p.count; i += hn::Lanes(df)) {
        const PlaneCrossing<PlaneLanes> c = crossings(p, i, ox, oy, oz, dx, dy, dz);
        const PlaneLanes t = leavingT(c);
        const auto better = hn::And(zero < c.den, t < best);
        best = select(better, t, best);
        bestFacet = hn::IfThenElse(hn::RebindMask(di, better), facetsAt(p, i), bestFacet);
    }
    const auto nearest = hn::MinOfLanes(df, best.v);
    hit = {hn::GetLane(nearest), lowestFacetAt(best, nearest, bestFacet)};
}

// Where the exit at distance t through the planes other than the girdle's is certainly nearer than any girdle
// plane (ConvexIntersector::Girdle), and an entry at t farther than any girdle plane the ray heads in through
// and nearer than any it heads out through: the point at t inside the cylinder within the stone's height, the
// ray's direction of length 1/2 to 2 and |t| bounded, so that the rounding of every value here and in the
// girdle planes' searches is a few float ulps of the stone's coordinates, far below the cylinder's margin.
template <class D>
HWY_INLINE hn::Mask<D> insideGirdle(const ConvexIntersector::Girdle& g, Lanes<D> ox, Lanes<D> oy, Lanes<D> oz,
                                    Lanes<D> dx, Lanes<D> dy, Lanes<D> dz, Lanes<D> t) {
    const Lanes<D> rx = ox + dx * t - Lanes<D>(g.cx), ry = oy + dy * t - Lanes<D>(g.cy), qz = oz + dz * t;
    const Lanes<D> length2 = dot3(dx, dy, dz, dx, dy, dz);
    auto inside = hn::And(rx * rx + ry * ry < Lanes<D>(g.radius2),
                          hn::And(-Lanes<D>(g.maxT) < t, t < Lanes<D>(g.maxT)));
    inside = hn::And(inside, hn::And(Lanes<D>(g.zLow) < qz, qz < Lanes<D>(g.zHigh)));
    return hn::And(inside, hn::And(Lanes<D>(0.25f) < length2, length2 < Lanes<D>(4.0f)));
}

// The nearer of two exits, the lower facet on a tie: what one search over both sets of planes picks.
HWY_INLINE void takeNearer(const SurfaceHit& h, SurfaceHit& best) {
    if (h.t < best.t || (h.t == best.t && h.facet < best.facet)) best = h;
}

// The nearest exit through the planes of `p` merged into each lane's (best, bestFacet), the lowest facet on
// ties whatever the order of the calls: after any sequence of them the lanes hold what one search over all
// their planes would.
HWY_INLINE void LeaveInto(const ConvexIntersector::Planes& p, PlaneLanes ox, PlaneLanes oy, PlaneLanes oz,
                          PlaneLanes dx, PlaneLanes dy, PlaneLanes dz, PlaneLanes& best,
                          hn::Vec<PlaneIndexTag>& bestFacet) {
    const PlaneTag df;
    const PlaneIndexTag di;
    const PlaneLanes zero(0.0f);
    for (size_t i = 0; i < p.count; i += hn::Lanes(df)) {
        const PlaneCrossing<PlaneLanes> c = crossings(p, i, ox, oy, oz, dx, dy, dz);
        const PlaneLanes t = leavingT(c);
        const auto facet = facetsAt(p, i);
        const auto better = hn::And(
            zero < c.den,
            hn::Or(t < best, hn::And(hn::Eq(t.v, best.v), hn::RebindMask(df, hn::Lt(facet, bestFacet)))));
        best = select(better, t, best);
        bestFacet = hn::IfThenElse(hn::RebindMask(di, better), facet, bestFacet);
    }
}

// The searches of LeaveCulled once the groups to search are known: `search`, then, when the exit found is
// not proven nearer than the hull's exit tq, the others.
HWY_INLINE void LeaveGroups(const ConvexIntersector::Cull& c, uint64_t search, bool proven, float tq,
                            const Vec3f& o, const Vec3f& d, SurfaceHit& hit) {
    const PlaneTag df;
    const PlaneIndexTag di;
    const PlaneLanes ox(o.x), oy(o.y), oz(o.z), dx(d.x), dy(d.y), dz(d.z);
    PlaneLanes best(kInf);
    auto bestFacet = hn::Zero(di);
    for (uint64_t left = search; left; left &= left - 1)
        LeaveInto(c.groups[size_t(__builtin_ctzll(left))], ox, oy, oz, dx, dy, dz, best, bestFacet);
    float nearest = hn::GetLane(hn::MinOfLanes(df, best.v));
    if (!(proven && nearest <= tq)) {
        const size_t groups = c.groups.size();
        const uint64_t all = groups == 64 ? ~uint64_t(0) : (uint64_t(1) << groups) - 1;
        for (uint64_t left = all & ~search; left; left &= left - 1)
            LeaveInto(c.groups[size_t(__builtin_ctzll(left))], ox, oy, oz, dx, dy, dz, best, bestFacet);
        nearest = hn::GetLane(hn::MinOfLanes(df, best.v));
    }
    hit = {nearest, lowestFacetAt(best, hn::Set(df, nearest), bestFacet)};
}

// The exit through every plane by the groups of ConvexIntersector::Cull. The ray leaves the hull at q, and
// the stone no later; the groups whose test passes at q have every plane farther along the ray than q, so the
// groups searched are those whose test fails there (a few), unless the exit found lies beyond q (an origin
// outside the stone): then every group. The tests are in float; the bounds were widened by the margin, which
// holds every rounding (o inside the hull, t and |d| bounded: q and each axis . q are within a few ulps of
// the stone's coordinates) and that of the planes' searches (for a plane that q lies m inside,
// num - t den > m, so its t exceeds q's by far more than its rounding).
HWY_INLINE void LeaveCulled(const ConvexIntersector::Cull& c, const Vec3f& o, const Vec3f& d,
                            SurfaceHit& hit) {
    const PlaneTag df;
    const size_t lanes = hn::Lanes(df), groups = c.groups.size();
    const PlaneLanes ox(o.x), oy(o.y), oz(o.z), dx(d.x), dy(d.y), dz(d.z), zero(0.0f);
    PlaneLanes hullT(kInf);
    auto inside = hn::FirstN(df, lanes);
    for (size_t i = 0; i < c.rows; i += lanes) {
        const PlaneLanes ax = PlaneLanes::load(&c.ax[i]), ay = PlaneLanes::load(&c.ay[i]),
                         az = PlaneLanes::load(&c.az[i]);
        const PlaneLanes den = dot3(dx, dy, dz, ax, ay, az),
                         num = PlaneLanes::load(&c.hullBound[i]) - dot3(ox, oy, oz, ax, ay, az),
                         t = num / den;
        hullT = select(hn::And(zero < den, t < hullT), t, hullT);
        inside = hn::And(inside, zero < num);
    }
    const float tq = hn::GetLane(hn::MinOfLanes(df, hullT.v)), length2 = dot(d, d);
    uint64_t search = groups == 64 ? ~uint64_t(0) : (uint64_t(1) << groups) - 1;
    const bool proven = hn::AllTrue(df, inside) && tq < c.maxT && 0.25f < length2 && length2 < 4.0f;
    if (proven) {
        const PlaneLanes qx(o.x + d.x * tq), qy(o.y + d.y * tq), qz(o.z + d.z * tq);
        for (size_t i = 0; i < groups; i += lanes) {
            const PlaneLanes along = dot3(PlaneLanes::load(&c.ax[i]), PlaneLanes::load(&c.ay[i]),
                                          PlaneLanes::load(&c.az[i]), qx, qy, qz);
            uint8_t bits[8] = {};
            hn::StoreMaskBits(df, along < PlaneLanes::load(&c.skipBelow[i]), bits);
            uint64_t word = 0;
            for (size_t b = 0; b < (lanes + 7) / 8; ++b) word |= uint64_t(bits[b]) << (8 * b);
            search &= ~(word << i);
        }
    }
    LeaveGroups(c, search, proven, tq, o, d, hit);
}

// ConvexIntersector::leave: the exit through every plane, the girdle's searched only where they may be it, or
// by the groups of the Cull.
HWY_INLINE bool LeaveStone(const ConvexIntersector& convex, const Vec3f& o, const Vec3f& d, SurfaceHit& hit) {
    if (const ConvexIntersector::Cull* c = convex.cull()) {
        LeaveCulled(*c, o, d, hit);
        return hit.t < kInf;
    }
    const ConvexIntersector::Girdle* g = convex.girdle();
    if (!g) {
        LeaveRay(convex.planes(), o, d, hit);
        return hit.t < kInf;
    }
    LeaveRay(g->others, o, d, hit);
    const PlaneTag df;
    if (!hn::AllTrue(df, insideGirdle(*g, PlaneLanes(o.x), PlaneLanes(o.y), PlaneLanes(o.z), PlaneLanes(d.x),
                                      PlaneLanes(d.y), PlaneLanes(d.z), PlaneLanes(hit.t)))) {
        SurfaceHit girdle;
        LeaveRay(g->facets, o, d, girdle);
        takeNearer(girdle, hit);
    }
    return hit.t < kInf;
}

HWY_INLINE bool EnterRay(const ConvexIntersector::Planes& p, const Vec3f& o, const Vec3f& d,
                         SurfaceHit& hit) {
    const PlaneTag df;
    const PlaneIndexTag di;
    const PlaneLanes ox(o.x), oy(o.y), oz(o.z), dx(d.x), dy(d.y), dz(d.z), zero(0.0f);
    PlaneLanes tIn(-kInf), tOut(kInf);
    auto outside = hn::FirstN(df, 0);
    auto inFacet = hn::Zero(di), facet = hn::Iota(di, 0);
    const auto step = hn::Set(di, int32_t(hn::Lanes(df)));
    for (size_t i = 0; i < p.count; i += hn::Lanes(df)) {
        const PlaneCrossing<PlaneLanes> c = crossings(p, i, ox, oy, oz, dx, dy, dz);
        const PlaneLanes t = c.num / c.den;
        tOut = select(hn::And(zero < c.den, t < tOut), t, tOut);
        const auto better = hn::And(c.den < zero, tIn < t);
        tIn = select(better, t, tIn);
        inFacet = hn::IfThenElse(hn::RebindMask(di, better), facet, inFacet);
        // A ray parallel to a plane it is outside of never enters.
        outside = hn::Or(outside, hn::And(hn::Eq(c.den.v, zero.v), c.num < zero));
        facet = hn::Add(facet, step);
    }
    const auto farthest = hn::MaxOfLanes(df, tIn.v);
    hit = {hn::GetLane(farthest), lowestFacetAt(tIn, farthest, inFacet)};
    return hit.t > 0 && hit.t <= hn::GetLane(hn::MinOfLanes(df, tOut.v)) && hn::AllFalse(df, outside);
}

// The beam's distance to plane i of `p` from origin o: a_i - dot(o, m_i).
template <class F>
HWY_INLINE F beamT(F a, F mx, F my, F mz, F ox, F oy, F oz) {
    return a - dot3(ox, oy, oz, mx, my, mz);
}

HWY_INLINE bool EnterBeamRay(const ConvexBeamEntry& beam, const Vec3f& o, SurfaceHit& hit) {
    const PlaneTag df;
    const PlaneIndexTag di;
    const PlaneLanes ox(o.x), oy(o.y), oz(o.z);
    const ConvexBeamEntry::Planes& in = beam.planes().in;
    PlaneLanes tIn(-kInf);
    auto inFacet = hn::Zero(di);
    for (size_t i = 0; i < in.count; i += hn::Lanes(df)) {
        const PlaneLanes t = beamT(PlaneLanes::load(&in.a[i]), PlaneLanes::load(&in.mx[i]),
                                   PlaneLanes::load(&in.my[i]), PlaneLanes::load(&in.mz[i]), ox, oy, oz);
        const auto better = tIn < t;
        tIn = select(better, t, tIn);
        inFacet = hn::IfThenElse(hn::RebindMask(di, better),
                                 hn::BitCast(di, hn::LoadU(hn::RebindToUnsigned<PlaneTag>(), &in.facet[i])),
                                 inFacet);
    }
    const auto farthest = hn::MaxOfLanes(df, tIn.v);
    hit = {hn::GetLane(farthest), lowestFacetAt(tIn, farthest, inFacet)};
    if (!(hit.t > 0)) return false;
    const ConvexBeamEntry::Planes& out = beam.planes().out;
    for (size_t i = 0; i < out.count; i += hn::Lanes(df)) {
        const PlaneLanes t = beamT(PlaneLanes::load(&out.a[i]), PlaneLanes::load(&out.mx[i]),
                                   PlaneLanes::load(&out.my[i]), PlaneLanes::load(&out.mz[i]), ox, oy, oz);
        if (!hn::AllFalse(df, t < PlaneLanes(hit.t))) return false;
    }
    const ConvexBeamEntry::Crossings& c = beam.planes();
    for (size_t i = 0; i < c.parallelOffset.size(); ++i) {
        if (dot(o, c.parallelNormal[i]) > c.parallelOffset[i]) return false;
    }
    return true;
}

// ---- A packet of rays, one per lane, against one plane at a time.
#if HWY_TARGET != HWY_SCALAR

using Facets = hn::Vec<IndexTag>;

// The nearest exit through the planes of `p` for each lane's ray, as LeaveRay gives it: t = +inf where there
// is none. Two searches over even and odd planes halve the chain of dependent compares.
HWY_INLINE void LeavePlanes(const ConvexIntersector::Planes& p, Floats ox, Floats oy, Floats oz, Floats dx,
                            Floats dy, Floats dz, Floats& tOut, Facets& facetOut) {
    const IndexTag di;
    const Floats zero(0.0f);
    Floats best[2] = {Floats(kInf), Floats(kInf)};
    Facets bestPlane[2] = {hn::Zero(di), hn::Zero(di)};
    Facets plane[2] = {hn::Set(di, 0), hn::Set(di, 1)};  // i in lanes, kept by adding rather than broadcast
    const Facets two = hn::Set(di, 2);
    auto visit = [&](size_t i, int chain) HWY_ATTR {
        const PlaneCrossing<Floats> c(ox, oy, oz, dx, dy, dz, Floats(p.nx[i]), Floats(p.ny[i]),
                                      Floats(p.nz[i]), Floats(p.offset[i]));
        const Floats t = leavingT(c);
        const auto better = hn::And(zero < c.den, t < best[chain]);
        best[chain] = select(better, t, best[chain]);
        bestPlane[chain] = hn::IfThenElse(hn::RebindMask(di, better), plane[chain], bestPlane[chain]);
    };
    size_t i = 0;
    for (; i + 1 < p.count; i += 2) {
        visit(i, 0);
        visit(i + 1, 1);
        plane[0] = hn::Add(plane[0], two), plane[1] = hn::Add(plane[1], two);
    }
    if (i < p.count) visit(i, 0);
    // The nearer of the two, and on a tie the lower plane, which is the lower facet (the planes are in facet
    // order), as LeaveRay picks.
    const auto odd =
        hn::Or(best[1] < best[0], hn::And(hn::Eq(best[1].v, best[0].v),
                                          hn::RebindMask(FloatTag(), hn::Lt(bestPlane[1], bestPlane[0]))));
    tOut = select(odd, best[1], best[0]);
    const Facets nearest = hn::IfThenElse(hn::RebindMask(di, odd), bestPlane[1], bestPlane[0]);
    facetOut = hn::GatherIndex(di, reinterpret_cast<const int32_t*>(p.facet.data()), nearest);
}

// LeaveCulled for each lane's ray in `live`: the hull's exit and the groups' tests for the packet, a row at a
// time (the same operations on each ray as LeaveCulled's), then each ray's groups one ray at a time: a
// packet's rays go every way, so they share few groups.
HWY_INLINE void LeaveEachCulled(const ConvexIntersector::Cull& c, FloatMask live, Floats ox, Floats oy,
                                Floats oz, Floats dx, Floats dy, Floats dz, Floats& tOut, Facets& facetOut) {
    constexpr size_t kMax = HWY_LANES(float);
    const FloatTag df;
    const Floats zero(0.0f);
    Floats hullT(kInf);
    FloatMask inside = live;
    for (size_t r = 0; r < c.rows; ++r) {
        const Floats ax(c.ax[r]), ay(c.ay[r]), az(c.az[r]);
        const Floats den = dot3(dx, dy, dz, ax, ay, az),
                     num = Floats(c.hullBound[r]) - dot3(ox, oy, oz, ax, ay, az), t = num / den;
        hullT = select(hn::And(zero < den, t < hullT), t, hullT);
        inside = hn::And(inside, zero < num);
    }
    const Floats length2 = dot3(dx, dy, dz, dx, dy, dz);
    const FloatMask proven = hn::And(hn::And(inside, hullT < Floats(c.maxT)),
                                     hn::And(Floats(0.25f) < length2, length2 < Floats(4.0f)));
    const Floats qx = ox + dx * hullT, qy = oy + dy * hullT, qz = oz + dz * hullT;
    uint64_t skip[kMax] = {};
    for (size_t g = 0; g < c.groups.size(); ++g) {
        const Floats along = dot3(Floats(c.ax[g]), Floats(c.ay[g]), Floats(c.az[g]), qx, qy, qz);
        uint8_t bits[8] = {};
        hn::StoreMaskBits(df, hn::And(proven, along < Floats(c.skipBelow[g])), bits);
        for (size_t k = 0; k < hn::Lanes(df); ++k) skip[k] |= uint64_t((bits[k / 8] >> (k % 8)) & 1) << g;
    }
    alignas(64) float t[kMax] = {}, tq[kMax], px[kMax], py[kMax], pz[kMax], vx[kMax], vy[kMax], vz[kMax];
    alignas(64) int32_t facet[kMax] = {};
    uint8_t liveBits[8] = {}, provenBits[8] = {};
    hullT.store(tq), ox.store(px), oy.store(py), oz.store(pz), dx.store(vx), dy.store(vy), dz.store(vz);
    hn::StoreMaskBits(df, live, liveBits);
    hn::StoreMaskBits(df, proven, provenBits);
    const size_t groups = c.groups.size();
    const uint64_t all = groups == 64 ? ~uint64_t(0) : (uint64_t(1) << groups) - 1;
    for (size_t k = 0; k < hn::Lanes(df); ++k) {
        if (!((liveBits[k / 8] >> (k % 8)) & 1)) continue;
        SurfaceHit hit;
        LeaveGroups(c, all & ~skip[k], (provenBits[k / 8] >> (k % 8)) & 1, tq[k], {px[k], py[k], pz[k]},
                    {vx[k], vy[k], vz[k]}, hit);
        t[k] = hit.t, facet[k] = int32_t(hit.facet);
    }
    tOut = Floats::load(t);
    facetOut = hn::LoadU(IndexTag(), facet);
}

// LeaveStone for each lane's ray in `live`. The girdle's planes are searched one ray at a time for the few
// rays that leave near the girdle: a packet's rays go every way, so the packet as a whole rarely could skip
// a plane.
HWY_INLINE void LeavePacket(const ConvexIntersector& convex, FloatMask live, Floats ox, Floats oy, Floats oz,
                            Floats dx, Floats dy, Floats dz, Floats& tOut, Facets& facetOut) {
    if (const ConvexIntersector::Cull* c = convex.cull()) {
        LeaveEachCulled(*c, live, ox, oy, oz, dx, dy, dz, tOut, facetOut);
        return;
    }
    const ConvexIntersector::Girdle* g = convex.girdle();
    LeavePlanes(g ? g->others : convex.planes(), ox, oy, oz, dx, dy, dz, tOut, facetOut);
    if (!g) return;
    const auto nearGirdle = hn::AndNot(insideGirdle(*g, ox, oy, oz, dx, dy, dz, tOut), live);
    if (hn::AllFalse(FloatTag(), nearGirdle)) return;
    constexpr size_t kMax = HWY_LANES(float);
    alignas(64) float t[kMax], px[kMax], py[kMax], pz[kMax], vx[kMax], vy[kMax], vz[kMax];
    alignas(64) int32_t facet[kMax];
    uint8_t bits[8] = {};
    tOut.store(t), ox.store(px), oy.store(py), oz.store(pz), dx.store(vx), dy.store(vy), dz.store(vz);
    hn::StoreU(facetOut, IndexTag(), facet);
    hn::StoreMaskBits(FloatTag(), nearGirdle, bits);
    for (size_t k = 0; k < hn::Lanes(FloatTag()); ++k) {
        if (!((bits[k / 8] >> (k % 8)) & 1)) continue;
        SurfaceHit girdle, hit{t[k], uint32_t(facet[k])};
        LeaveRay(g->facets, {px[k], py[k], pz[k]}, {vx[k], vy[k], vz[k]}, girdle);
        takeNearer(girdle, hit);
        t[k] = hit.t, facet[k] = int32_t(hit.facet);
    }
    tOut = Floats::load(t);
    facetOut = hn::LoadU(IndexTag(), facet);
}

// Each lane's beam ray against the planes of `c`: the farthest plane it heads in through (the lowest facet on
// ties), the nearest it heads out through, and whether it is inside every plane parallel to it.
struct BeamCrossings {
    Floats tIn, tExit;
    Facets inFacet;
    FloatMask inside;
};
HWY_INLINE BeamCrossings crossBeam(const ConvexBeamEntry::Crossings& c, Floats ox, Floats oy, Floats oz) {
    const IndexTag di;
    BeamCrossings x{Floats(-kInf), Floats(kInf), hn::Zero(di), hn::FirstN(FloatTag(), HWY_LANES(float))};
    for (size_t i = 0; i < c.in.count; ++i) {
        const Floats t =
            beamT(Floats(c.in.a[i]), Floats(c.in.mx[i]), Floats(c.in.my[i]), Floats(c.in.mz[i]), ox, oy, oz);
        const auto better = x.tIn < t;
        x.tIn = select(better, t, x.tIn);
        x.inFacet =
            hn::IfThenElse(hn::RebindMask(di, better), hn::Set(di, int32_t(c.in.facet[i])), x.inFacet);
    }
    for (size_t i = 0; i < c.out.count; ++i) {
        const Floats t = beamT(Floats(c.out.a[i]), Floats(c.out.mx[i]), Floats(c.out.my[i]),
                               Floats(c.out.mz[i]), ox, oy, oz);
        x.tExit = select(t < x.tExit, t, x.tExit);
    }
    for (size_t i = 0; i < c.parallelOffset.size(); ++i) {
        const Vec3f& n = c.parallelNormal[i];
        const Floats side = dot3(ox, oy, oz, Floats(n.x), Floats(n.y), Floats(n.z));
        x.inside = hn::AndNot(Floats(c.parallelOffset[i]) < side, x.inside);
    }
    return x;
}

// EnterBeamRay for each lane's origin: the lanes that enter, each with its t and facet. The girdle's planes
// (ConvexBeamEntry::girdle) are crossed only when a lane enters near the girdle.
HWY_INLINE FloatMask EnterBeamPacket(const ConvexBeamEntry& beam, Floats ox, Floats oy, Floats oz,
                                     Floats& tOut, Facets& facetOut) {
    const ConvexIntersector::Girdle* g = beam.girdle();
    BeamCrossings x = crossBeam(g ? beam.otherFacets() : beam.planes(), ox, oy, oz);
    if (g) {
        const Floats dx(beam.direction().x), dy(beam.direction().y), dz(beam.direction().z);
        if (!hn::AllTrue(FloatTag(), insideGirdle(*g, ox, oy, oz, dx, dy, dz, x.tIn))) {
            // As one search over both sets of planes: the farther entry and on a tie the lower facet, the
            // nearer exit.
            const BeamCrossings y = crossBeam(beam.girdleFacets(), ox, oy, oz);
            const auto girdle = hn::Or(
                x.tIn < y.tIn,
                hn::And(hn::Eq(y.tIn.v, x.tIn.v), hn::RebindMask(FloatTag(), hn::Lt(y.inFacet, x.inFacet))));
            x.tIn = select(girdle, y.tIn, x.tIn);
            x.inFacet = hn::IfThenElse(hn::RebindMask(IndexTag(), girdle), y.inFacet, x.inFacet);
            x.tExit = select(y.tExit < x.tExit, y.tExit, x.tExit);
            x.inside = hn::And(x.inside, y.inside);
        }
    }
    tOut = x.tIn;
    facetOut = x.inFacet;
    return hn::And(x.inside, hn::AndNot(x.tExit < x.tIn, Floats(0.0f) < x.tIn));
}
#endif  // HWY_TARGET != HWY_SCALAR

}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#endif
