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
#include "util/detail/lanes-inl.h"

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

HWY_INLINE bool LeaveRay(const ConvexIntersector::Planes& p, const Vec3f& o, const Vec3f& d,
                         SurfaceHit& hit) {
    const PlaneTag df;
    const PlaneIndexTag di;
    const PlaneLanes ox(o.x), oy(o.y), oz(o.z), dx(d.x), dy(d.y), dz(d.z), zero(0.0f);
    PlaneLanes best(kInf);
    auto bestFacet = hn::Zero(di), facet = hn::Iota(di, 0);
    const auto step = hn::Set(di, int32_t(hn::Lanes(df)));
    for (size_t i = 0; i < p.count; i += hn::Lanes(df)) {
        const PlaneCrossing<PlaneLanes> c = crossings(p, i, ox, oy, oz, dx, dy, dz);
        const PlaneLanes t = leavingT(c);
        const auto better = hn::And(zero < c.den, t < best);
        best = select(better, t, best);
        bestFacet = hn::IfThenElse(hn::RebindMask(di, better), facet, bestFacet);
        facet = hn::Add(facet, step);
    }
    const auto nearest = hn::MinOfLanes(df, best.v);
    hit = {hn::GetLane(nearest), lowestFacetAt(best, nearest, bestFacet)};
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
    const ConvexBeamEntry::Planes& in = beam.in();
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
    const ConvexBeamEntry::Planes& out = beam.out();
    for (size_t i = 0; i < out.count; i += hn::Lanes(df)) {
        const PlaneLanes t = beamT(PlaneLanes::load(&out.a[i]), PlaneLanes::load(&out.mx[i]),
                                   PlaneLanes::load(&out.my[i]), PlaneLanes::load(&out.mz[i]), ox, oy, oz);
        if (!hn::AllFalse(df, t < PlaneLanes(hit.t))) return false;
    }
    for (size_t i = 0; i < beam.parallelOffsets().size(); ++i) {
        if (dot(o, beam.parallelNormals()[i]) > beam.parallelOffsets()[i]) return false;
    }
    return true;
}

// ---- A packet of rays, one per lane, against one plane at a time.
#if HWY_TARGET != HWY_SCALAR

using Facets = hn::Vec<IndexTag>;

// LeaveRay for each lane's ray: t and facet as LeaveRay gives them, t = +inf where it finds no way out. Two
// searches over even and odd planes halve the chain of dependent compares.
HWY_INLINE void LeavePacket(const ConvexIntersector::Planes& p, Floats ox, Floats oy, Floats oz, Floats dx,
                            Floats dy, Floats dz, Floats& tOut, Facets& facetOut) {
    const IndexTag di;
    const Floats zero(0.0f);
    Floats best[2] = {Floats(kInf), Floats(kInf)};
    Facets bestFacet[2] = {hn::Zero(di), hn::Zero(di)};
    Facets plane[2] = {hn::Set(di, 0), hn::Set(di, 1)};  // i in lanes, kept by adding rather than broadcast
    const Facets two = hn::Set(di, 2);
    auto visit = [&](size_t i, int chain) HWY_ATTR {
        const PlaneCrossing<Floats> c(ox, oy, oz, dx, dy, dz, Floats(p.nx[i]), Floats(p.ny[i]),
                                      Floats(p.nz[i]), Floats(p.offset[i]));
        const Floats t = leavingT(c);
        const auto better = hn::And(zero < c.den, t < best[chain]);
        best[chain] = select(better, t, best[chain]);
        bestFacet[chain] = hn::IfThenElse(hn::RebindMask(di, better), plane[chain], bestFacet[chain]);
    };
    size_t i = 0;
    for (; i + 1 < p.count; i += 2) {
        visit(i, 0);
        visit(i + 1, 1);
        plane[0] = hn::Add(plane[0], two), plane[1] = hn::Add(plane[1], two);
    }
    if (i < p.count) visit(i, 0);
    // The nearer of the two, and on a tie the lower plane, as LeaveRay picks.
    const auto odd =
        hn::Or(best[1] < best[0], hn::And(hn::Eq(best[1].v, best[0].v),
                                          hn::RebindMask(FloatTag(), hn::Lt(bestFacet[1], bestFacet[0]))));
    tOut = select(odd, best[1], best[0]);
    facetOut = hn::IfThenElse(hn::RebindMask(di, odd), bestFacet[1], bestFacet[0]);
}

// EnterBeamRay for each lane's origin: the lanes that enter, each with its t and facet.
HWY_INLINE FloatMask EnterBeamPacket(const ConvexBeamEntry& beam, Floats ox, Floats oy, Floats oz,
                                     Floats& tOut, Facets& facetOut) {
    const IndexTag di;
    const ConvexBeamEntry::Planes& in = beam.in();
    const ConvexBeamEntry::Planes& out = beam.out();
    Floats tIn(-kInf), tExit(kInf);
    Facets inFacet = hn::Zero(di);
    for (size_t i = 0; i < in.count; ++i) {
        const Floats t =
            beamT(Floats(in.a[i]), Floats(in.mx[i]), Floats(in.my[i]), Floats(in.mz[i]), ox, oy, oz);
        const auto better = tIn < t;
        tIn = select(better, t, tIn);
        inFacet = hn::IfThenElse(hn::RebindMask(di, better), hn::Set(di, int32_t(in.facet[i])), inFacet);
    }
    for (size_t i = 0; i < out.count; ++i) {
        const Floats t =
            beamT(Floats(out.a[i]), Floats(out.mx[i]), Floats(out.my[i]), Floats(out.mz[i]), ox, oy, oz);
        tExit = select(t < tExit, t, tExit);
    }
    auto enters = hn::AndNot(tExit < tIn, Floats(0.0f) < tIn);
    for (size_t i = 0; i < beam.parallelOffsets().size(); ++i) {
        const Vec3f& n = beam.parallelNormals()[i];
        const Floats side = dot3(ox, oy, oz, Floats(n.x), Floats(n.y), Floats(n.z));
        enters = hn::AndNot(Floats(beam.parallelOffsets()[i]) < side, enters);
    }
    tOut = tIn;
    facetOut = inFacet;
    return enters;
}
#endif  // HWY_TARGET != HWY_SCALAR

}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#endif
