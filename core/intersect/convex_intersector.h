#pragma once
// Ray casting against a convex stone by its facet planes alone: the ray is inside the stone where it is
// inside every half-space, so the exit facet is the plane with the smallest t among those the ray heads out
// through, and the entry facet the one with the largest t among those it heads in through (the slab test,
// generalised). The searches are written once over SIMD lanes (intersect/detail/convex_search-inl.h) and
// compiled for every target; the CPU's best is picked when an intersector is built. Every target computes
// the same bits: each (ray, plane) pair takes the same correctly rounded operations, and ties go to the
// lowest facet.
#include <cstdint>
#include <vector>

#include "geometry/ray.h"
#include "stone/stone.h"

namespace facetlight {

// The searches of one SIMD target (intersect/detail/convex_kernels.h).
struct ConvexKernels;

class ConvexIntersector {
  public:
    // Uses the facet planes of `stone`, which must be convex (stone.convex).
    explicit ConvexIntersector(const Stone& stone);

    // A ray from outside: the first facet it crosses into the stone; false when it misses.
    bool enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    // A ray from a point inside or on the surface: the facet it leaves through, at t >= 0 (a point a rounding
    // error outside a plane it heads out through leaves at once). Always true for a closed convex stone.
    bool leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;

    // The facet planes as a structure of arrays, `count` of them, padded to a multiple of kPadding with
    // planes of zero normal and offset 1 (neither entered nor left), for the searches.
    struct Planes {
        static constexpr size_t kPadding = 16;  // floats in the widest SIMD register (AVX-512)
        size_t count = 0;
        std::vector<float> nx, ny, nz, offset;
    };
    const Planes& planes() const { return planes_; }

  private:
    Planes planes_;
    const ConvexKernels* kernels_;
};

// Entry into a convex stone along one fixed direction (a collimated beam). Every photon shares dot(dir, n)
// per plane, so the divisions are done once: the ray from o meets plane i at t = a_i - dot(o, m_i) with
// a_i = offset_i / dot(dir, n_i) and m_i = n_i / dot(dir, n_i). Same contract as ConvexIntersector::enter.
class ConvexBeamEntry {
  public:
    ConvexBeamEntry(const Stone& stone, const Vec3f& dir);
    bool enter(const Vec3f& origin, SurfaceHit& hit) const;

    // The planes the beam heads in through (padding at a = -inf) and those it heads out through (padding at
    // a = +inf), each in facet order, padded to ConvexIntersector::Planes::kPadding.
    struct Planes {
        size_t count = 0;
        std::vector<float> a, mx, my, mz;
        std::vector<uint32_t> facet;
        void add(float a_, const Vec3f& m, uint32_t f);
        void pad(float a_);
    };
    const Planes& in() const { return in_; }
    const Planes& out() const { return out_; }
    // Planes parallel to the beam: a ray outside one of them misses the stone.
    const std::vector<Vec3f>& parallelNormals() const { return parallelNormal_; }
    const std::vector<float>& parallelOffsets() const { return parallelOffset_; }

  private:
    Planes in_, out_;
    std::vector<Vec3f> parallelNormal_;
    std::vector<float> parallelOffset_;
    const ConvexKernels* kernels_;
};

}  // namespace facetlight
