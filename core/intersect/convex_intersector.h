#pragma once
// Ray casting against a convex stone by its facet planes alone: the ray is inside the stone where it is
// inside every half-space, so the exit facet is the plane with the smallest t among those the ray heads out
// through, and the entry facet the one with the largest t among those it heads in through (the slab test,
// generalised). The planes are kept as a structure of arrays padded to the SIMD width, and the loop over them
// has no branches.
#include <vector>

#include "geometry/ray.h"
#include "stone/stone.h"

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
#if FACETLIGHT_PACKETS
    // leave() for sixteen rays at once: each lane gets the t and facet leave() gives its ray, t = +inf
    // where it finds no way out.
    void leave(const RayPacket& rays, Floats16& t, __m512i& facet) const;
#endif

#if defined(__AVX512F__)
    static constexpr size_t kWidth = 16;  // floats per SIMD register (AVX-512)
#else
    static constexpr size_t kWidth = 8;  // floats per SIMD register (AVX2)
#endif

  private:
    size_t planes_ = 0, padded_ = 0;
    // Padding planes have a zero normal, so they are neither entered nor left.
    std::vector<float> nx_, ny_, nz_, offset_;
};

// Entry into a convex stone along one fixed direction (a collimated beam). Every photon shares dot(dir, n)
// per plane, so the divisions are done once: the ray from o meets plane i at t = a_i - dot(o, m_i) with
// a_i = offset_i / dot(dir, n_i) and m_i = n_i / dot(dir, n_i). Same contract as ConvexIntersector::enter.
class ConvexBeamEntry {
  public:
    ConvexBeamEntry(const Stone& stone, const Vec3f& dir);
    bool enter(const Vec3f& origin, SurfaceHit& hit) const;
#if FACETLIGHT_PACKETS
    // enter() for sixteen origins at once: the lanes that enter, each with the t and facet enter() gives.
    LaneMask enter(const Floats16& ox, const Floats16& oy, const Floats16& oz, Floats16& t,
                   __m512i& facet) const;
#endif

  private:
    // A structure of arrays padded to kWidth, for the planes the beam heads in through (padding at
    // t = -inf) and those it heads out through (padding at t = +inf).
    struct Planes {
        std::vector<float> a, mx, my, mz;
        std::vector<uint32_t> facet;
        void add(float a_, const Vec3f& m, uint32_t f);
        void pad(float a_);
    };
    Planes in_, out_;
    // The positions in in_ of its real planes, in the order enter() settles ties: by position modulo kWidth
    // (its SIMD lane), then by position.
    std::vector<uint32_t> inTieOrder_;
    // Planes parallel to the beam: a ray outside one of them misses the stone.
    std::vector<Vec3f> parallelNormal_;
    std::vector<float> parallelOffset_;
};

}  // namespace facetlight
