#pragma once
// What the renderer sees: the stone above a diffuse floor, lit by the job's light model, inside a studio
// environment (soft light panels above, dark below, the viewer's own dark silhouette above the stone: the
// contrast that makes a diamond sparkle).
//
// Geometry is kept in the stone's frame, as the tracer keeps it: a tilted stone is the world rotated by
// -tilt about x. The floor is horizontal in the world, under the stone's lowest point.
#include <memory>
#include <vector>

#include "geometry/geometry.h"
#include "geometry/ray.h"
#include "optics/light_model.h"
#include "optics/material.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/random.h"

namespace facetlight {

class ConvexIntersector;
class EmbreeIntersector;
struct PhotonPath;

class Scene {
  public:
    // The stone must outlive the scene. Throws Error for settings the tracer would refuse.
    Scene(const Stone& stone, const TraceSettings& settings);
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    const Stone& stone() const { return stone_; }
    Vec3 toWorld(const Vec3& v) const;
    Vec3 toStone(const Vec3& v) const;
    const Vec3& up() const { return up_; }          // the world's vertical, in the stone's frame
    const Vec3& center() const { return center_; }  // of the stone's bounds, stone frame
    double diameter() const { return diameter_; }   // girdle diameter (or width): the camera's unit

    // Ray casts against the stone (see ConvexIntersector for the contracts).
    bool enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    bool leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    const Vec3f& normal(uint32_t facet) const { return normal_[facet]; }
    double index(double wavelengthNm) const { return material_.index(wavelengthNm); }
    // Whether refraction depends on the wavelength in this job (dispersion asked for, material dispersive).
    bool dispersive() const { return dispersive_; }

    // Distance along a ray to the floor; false when it never gets there.
    bool hitFloor(const Vec3& origin, const Vec3& dir, double& t) const;
    static constexpr double kFloorAlbedo = 0.35;

    // Irradiance at floor point p of the light that reaches it without passing through the stone (a shadow
    // ray: light through the stone arrives as caustic photons). Units: a collimated beam has irradiance 1 on
    // a plane facing it; a hemisphere gives an open floor 1; a point light gives 1 at the stone's centre.
    double directIrradiance(const Vec3& p, Rng& rng) const;
    // The power of each of `count` photons drawn from the light model, in the same units.
    double photonPower(uint64_t count) const;
    // Where a photon that left the stone (or was reflected off it) lands on the floor; false when it goes
    // up, or would meet the stone again.
    bool landOnFloor(const PhotonPath& path, Vec3& position) const;

    // Radiance of the studio along world direction `dir`; `toViewer` is the world direction from the stone
    // to the camera, whose surroundings are dark (the observer's head and the camera).
    static double environment(const Vec3& dir, const Vec3& toViewer);

  private:
    const Stone& stone_;
    TraceSettings settings_;
    Material material_;
    LightModel light_;
    bool dispersive_ = false;
    double cosTilt_ = 1, sinTilt_ = 0;
    Vec3 up_, center_;
    double diameter_ = 1;
    double floorHeight_ = 0;  // dot(up, p) on the floor
    Vec3 lightDir_;           // collimated: direction of travel, stone frame
    Vec3 lightPos_;           // point: stone frame
    double pointIntensity_ = 0;
    double cosShadow3_ = 1;  // hemisphere: cos^3 of the head-shadow half-angle
    std::vector<Vec3f> normal_;
    std::unique_ptr<ConvexIntersector> convex_;
    std::unique_ptr<EmbreeIntersector> embree_;
};

}  // namespace facetlight
