#include "intersect/convex_intersector.h"

#include <limits>

#include "util/error.h"

// Compiled once per SIMD target (Highway's foreach_target re-includes this file).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "intersect/convex_intersector.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "intersect/detail/convex_kernels.h"
#include "intersect/detail/convex_search-inl.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {

bool enterOne(const ConvexIntersector::Planes& p, const Vec3f& o, const Vec3f& d, SurfaceHit& hit) {
    return EnterRay(p, o, d, hit);
}
bool leaveOne(const ConvexIntersector::Planes& p, const Vec3f& o, const Vec3f& d, SurfaceHit& hit) {
    return LeaveRay(p, o, d, hit);
}
bool enterBeamOne(const ConvexBeamEntry& beam, const Vec3f& o, SurfaceHit& hit) {
    return EnterBeamRay(beam, o, hit);
}
const ConvexKernels* convexKernels() {
    static const ConvexKernels kernels{&enterOne, &leaveOne, &enterBeamOne};
    return &kernels;
}

}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facetlight {

HWY_EXPORT(convexKernels);

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace

ConvexIntersector::ConvexIntersector(const Stone& stone) : kernels_(HWY_DYNAMIC_DISPATCH(convexKernels)()) {
    if (!stone.convex)
        throw Error("the convex intersector needs a convex stone; '" + stone.name + "' is not");
    if (stone.facets.empty()) throw Error("stone '" + stone.name + "' has no facets");
    const size_t n = stone.facets.size(),
                 padded = (n + Planes::kPadding - 1) / Planes::kPadding * Planes::kPadding;
    planes_.count = n;
    planes_.nx.assign(padded, 0.0f);
    planes_.ny.assign(padded, 0.0f);
    planes_.nz.assign(padded, 0.0f);
    planes_.offset.assign(padded, 1.0f);
    for (size_t i = 0; i < n; ++i) {
        const Facet& f = stone.facets[i];
        planes_.nx[i] = float(f.normal.x);
        planes_.ny[i] = float(f.normal.y);
        planes_.nz[i] = float(f.normal.z);
        planes_.offset[i] = float(f.offset);
    }
}

bool ConvexIntersector::enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const {
    return kernels_->enter(planes_, origin, dir, hit);
}

bool ConvexIntersector::leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const {
    return kernels_->leave(planes_, origin, dir, hit);
}

void ConvexBeamEntry::Planes::add(float a_, const Vec3f& m, uint32_t f) {
    a.push_back(a_);
    mx.push_back(m.x);
    my.push_back(m.y);
    mz.push_back(m.z);
    facet.push_back(f);
}

void ConvexBeamEntry::Planes::pad(float a_) {
    count = a.size();
    while (a.empty() || a.size() % ConvexIntersector::Planes::kPadding) add(a_, {}, 0);
}

ConvexBeamEntry::ConvexBeamEntry(const Stone& stone, const Vec3f& dir)
    : kernels_(HWY_DYNAMIC_DISPATCH(convexKernels)()) {
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
    in_.pad(-kInf);
    out_.pad(kInf);
}

bool ConvexBeamEntry::enter(const Vec3f& origin, SurfaceHit& hit) const {
    return kernels_->enterBeam(*this, origin, hit);
}

}  // namespace facetlight
#endif
