#pragma once
// Ray casting against a convex stone by its facet planes alone: the ray is inside the stone where it is
// inside every half-space, so the exit facet is the plane with the smallest t among those the ray heads out
// through, and the entry facet the one with the largest t among those it heads in through (the slab test,
// generalised). The planes are kept as a structure of arrays padded to the SIMD width, and the loop over them
// has no branches.
#include <vector>

#include "ray.h"
#include "stone.h"

namespace facetlight {

class ConvexIntersector {
  public:
    // Uses the facet planes of `stone`, which must be convex (stone.convex).
    explicit ConvexIntersector(const Stone& stone);

    // A ray from outside: the first facet it crosses into the stone; false when it misses.
    bool enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    // A ray from a point inside or on the surface: the facet it leaves through, at t >= 0 (a point a rounding
    // error outside a plane it heads out through leaves at once). Always true for a closed convex stone.
    bool leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;

    static constexpr size_t kWidth = 8;  // floats per SIMD register (AVX2)

  private:
    size_t padded_ = 0;
    // Padding planes have a zero normal, so they are neither entered nor left.
    std::vector<float> nx_, ny_, nz_, offset_;
};

}  // namespace facetlight
