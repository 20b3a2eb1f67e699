#pragma once
// Ray casting against any closed stone mesh with Embree 3 (one BVH over the triangles), for the stones the
// convex intersector cannot take. Queries are thread-safe; the scene is built once in the constructor.
#include <cstdint>
#include <vector>

#include "geometry/ray.h"
#include "stone/stone.h"

struct RTCDeviceTy;
struct RTCSceneTy;

namespace facetlight {

class EmbreeIntersector {
  public:
    explicit EmbreeIntersector(const Stone& stone);
    ~EmbreeIntersector();
    EmbreeIntersector(const EmbreeIntersector&) = delete;
    EmbreeIntersector& operator=(const EmbreeIntersector&) = delete;

    // Same contracts as ConvexIntersector: the first facet crossed inward from outside, and the facet a ray
    // from inside (or from a point on the surface) leaves through. False when there is none.
    bool enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    bool leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;

  private:
    bool cast(const Vec3f& origin, const Vec3f& dir, float tnear, SurfaceHit& hit) const;

    RTCDeviceTy* device_ = nullptr;
    RTCSceneTy* scene_ = nullptr;
    std::vector<uint32_t> triangleFacet_;
    std::vector<Vec3f> facetNormal_;
    float selfHitEpsilon_ = 0;  // how far behind a surface point a ray leaving it starts
};

}  // namespace facetlight
