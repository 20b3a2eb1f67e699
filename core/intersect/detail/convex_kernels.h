#pragma once
// Inside the intersectors (not for use outside core/): the one-ray searches of one SIMD target, picked once
// when an intersector is built, so that a ray costs one indirect call and no dispatch.
#include "intersect/convex_intersector.h"

namespace facetlight {

struct ConvexKernels {
    bool (*enter)(const ConvexIntersector::Planes&, const Vec3f& origin, const Vec3f& dir, SurfaceHit&);
    bool (*leave)(const ConvexIntersector&, const Vec3f& origin, const Vec3f& dir, SurfaceHit&);
    bool (*enterBeam)(const ConvexBeamEntry&, const Vec3f& origin, SurfaceHit&);
};

}  // namespace facetlight
