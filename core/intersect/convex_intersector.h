#pragma once
// Ray casting against a convex stone by its facet planes alone: the ray is inside the stone where it is
// inside every half-space, so the exit facet is the plane with the smallest t among those the ray heads out
// through, and the entry facet the one with the largest t among those it heads in through (the slab test,
// generalised). The searches are written once over SIMD lanes (intersect/convex_search-inl.h) and
// compiled for every target; the CPU's best is picked when an intersector is built. Every target computes
// the same bits: each (ray, plane) pair takes the same correctly rounded operations, and ties go to the
// lowest facet.
//
// The exit search skips the girdle of a round stone where it cannot be the answer (Girdle below): the shipped
// brilliant's 64 girdle facets are more than half its planes, and a ray leaves through them only near the
// girdle. A stone of many planes without such a girdle (briolettes, checkerboards, step cuts of 200 facets)
// has its planes searched in groups instead (Cull below), only the groups that may hold the exit. Either
// way the answer stays bit for bit that of the search over every plane.
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

    // Facet planes as a structure of arrays, `count` of them in increasing facet order, padded to a multiple
    // of kPadding with planes of zero normal and offset 1 (neither entered nor left), for the searches.
    struct Planes {
        static constexpr size_t kPadding = 16;  // floats in the widest SIMD register (AVX-512)
        size_t count = 0;
        std::vector<float> nx, ny, nz, offset;
        std::vector<uint32_t> facet;  // each plane's index in Stone::facets
        void add(const Facet& f);
        void pad();
    };
    // Every facet's plane, facet i at i.
    const Planes& planes() const { return planes_; }

    // The girdle's facets, searched apart: planes whose normals lie within 30 deg of horizontal and which
    // all contain an upright cylinder about the stone's axis that reaches at least 98 % of the stone's widest
    // radius (a round girdle). An exit through the other facets at a point inside that cylinder, shrunk by
    // a margin far above the rounding of the search, is nearer than any girdle plane, so the girdle is
    // searched only for rays that leave near it. Absent (null) unless there are at least 8 such planes.
    struct Girdle {
        Planes facets;              // the girdle's planes
        Planes others;              // every other plane
        float cx = 0, cy = 0;       // the cylinder's axis
        float radius2 = 0;          // its radius, less the margin, squared
        float zLow = 0, zHigh = 0;  // the stone's height range and a margin: the cylinder's height
        float maxT = 0;  // rays longer than this (or of a length far from 1) take the girdle search too
    };
    const Girdle* girdle() const { return girdle_.facets.count ? &girdle_ : nullptr; }

    // The planes of a stone without a girdle to skip, in groups of nearby normals (k-means), each group in
    // facet order, and a hull: the stone widened by a margin m (1e-4 of its coordinates and size, as the
    // girdle's) along each group's axis and the six axis directions (axis_h . x < hullBound_h). A ray from
    // inside leaves the hull at some q, and the stone no later; a group g whose every plane lies farther than
    // q along the ray may be skipped, which holds when axis_g . q < skipBelow_g: the least axis_g . x over
    // the points x of the hull widened by m that lie less than m inside a plane of g (a linear programme over
    // the hull's vertices and edges, solved once per stone). m is far above the rounding of q and of the
    // planes' searches, so the answer stays bit for bit the exit through every plane (convex_search-inl.h,
    // LeaveCulled). Absent (no groups) for stones of fewer than kMinPlanes planes, or with a girdle.
    struct Cull {
        static constexpr size_t kMinPlanes = 96;
        static constexpr size_t kMaxGroups = 64, kMaxRows = 80;  // a bit set of groups; 64 + 6 rows, padded
        std::vector<Planes> groups;
        size_t rows = 0;  // groups, then the six axis directions; the arrays are padded to kPadding
        std::vector<float> ax, ay, az, hullBound, skipBelow;  // skipBelow = -inf on the six rows
        float maxT = 0;  // rays longer than this (or of a length far from 1) search every group
    };
    const Cull* cull() const { return cull_.groups.empty() ? nullptr : &cull_; }

    // Whether intersectors built from now on use the Cull (true, the default): false gives the search over
    // every plane, for benchmarks and tests to compare. The girdle skip stays either way.
    static void setCulling(bool on);

  private:
    Planes planes_;
    Girdle girdle_;
    Cull cull_;
    const ConvexKernels* kernels_;
};

// Entry into a convex stone along one fixed direction (a collimated beam). Every photon shares dot(dir, n)
// per plane, so the divisions are done once: the ray from o meets plane i at t = a_i - dot(o, m_i) with
// a_i = offset_i / dot(dir, n_i) and m_i = n_i / dot(dir, n_i). Same contract as ConvexIntersector::enter.
class ConvexBeamEntry {
  public:
    ConvexBeamEntry(const Stone& stone, const Vec3f& dir);
    bool enter(const Vec3f& origin, SurfaceHit& hit) const;
    const Vec3f& direction() const { return dir_; }

    // Planes of a, m, facet, padded to ConvexIntersector::Planes::kPadding.
    struct Planes {
        size_t count = 0;
        std::vector<float> a, mx, my, mz;
        std::vector<uint32_t> facet;
        void add(float a_, const Vec3f& m, uint32_t f);
        void pad(float a_);
    };
    // Facet planes as the beam meets them: those it heads in through (padding at a = -inf) and those it heads
    // out through (padding at a = +inf), each in facet order, and those parallel to it: a ray outside one of
    // them misses the stone.
    struct Crossings {
        Planes in, out;
        std::vector<Vec3f> parallelNormal;
        std::vector<float> parallelOffset;
    };
    // Every facet's plane.
    const Crossings& planes() const { return planes_; }
    // Parted as the exit search parts them (ConvexIntersector::Girdle): the girdle's planes matter only for
    // rays that enter near the girdle. girdle() is null where the stone has no such girdle.
    const ConvexIntersector::Girdle* girdle() const { return girdle_.facets.count ? &girdle_ : nullptr; }
    const Crossings& girdleFacets() const { return girdleFacets_; }
    const Crossings& otherFacets() const { return otherFacets_; }

  private:
    Vec3f dir_;
    Crossings planes_, girdleFacets_, otherFacets_;
    ConvexIntersector::Girdle girdle_;
    const ConvexKernels* kernels_;
};

}  // namespace facetlight
