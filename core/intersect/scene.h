#pragma once
// What every phase of a study sees, prepared once per study: the stone with its one intersector (convex or
// Embree), the material and the light model, the photon tracer's precomputed entries; and, for the renderer,
// the stone above a diffuse floor inside a studio environment (soft light panels above, dark below, the
// viewer's own dark silhouette above the stone: the contrast that makes a diamond sparkle). The statistics
// trace, the photon pass and the renderer share it.
//
// Geometry is kept in the stone's frame: a tilted stone is the world rotated by -tilt about x. The floor is
// horizontal in the world, under the stone's lowest point.
#include <array>
#include <memory>
#include <vector>

#include "geometry/geometry.h"
#include "geometry/ray.h"
#include "optics/light_model.h"
#include "optics/material.h"
#include "stats/facet_stats.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/random.h"

namespace facetlight {

class ConvexBeamEntry;
class ConvexIntersector;
class EmbreeIntersector;
struct PhotonPath;

class Scene {
  public:
    // Validates the settings once. Throws Error for settings that cannot be traced on this stone (e.g.
    // intersector "convex" on a non-convex stone). The stone must outlive the scene.
    Scene(const Stone& stone, const TraceSettings& settings);
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    const Stone& stone() const { return stone_; }
    const TraceSettings& settings() const { return settings_; }
    bool usesEmbree() const { return embree_ != nullptr; }

    Vec3 toWorld(const Vec3& v) const;
    Vec3 toStone(const Vec3& v) const;
    const Vec3& up() const { return vertical_; }    // the world's vertical, in the stone's frame
    const Vec3& center() const { return center_; }  // of the stone's bounds, stone frame
    double diameter() const { return diameter_; }   // girdle diameter (or width): the camera's unit

    // Ray casts against the stone (see ConvexIntersector for the contracts).
    bool enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    bool leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    const Vec3f& normal(uint32_t facet) const { return normal_[facet]; }
    double index(double wavelengthNm) const { return material_.index(wavelengthNm); }
    // Whether refraction depends on the wavelength in this job (dispersion asked for, material dispersive):
    // then each photon has its own wavelength and index.
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
    friend class PhotonWalker;
    const Stone& stone_;
    TraceSettings settings_;
    Material material_;
    LightModel light_;
    bool dispersive_ = false;
    float fixedIndex_;  // the index at 589.3 nm, used when dispersion is off
    std::vector<Region> facetRegion_;
    std::vector<Vec3f> normal_;
    double cosTilt_ = 1, sinTilt_ = 0;
    Vec3 vertical_, center_;
    Vec3f up_;  // vertical_ in float, for the tracer's tallies
    double diameter_ = 1;
    double floorHeight_ = 0;  // dot(up, p) on the floor
    Vec3 lightDir_;           // collimated: direction of travel, stone frame
    Vec3 lightPos_;           // point: stone frame
    double pointIntensity_ = 0;
    double cosShadow3_ = 1;  // hemisphere: cos^3 of the head-shadow half-angle
    float cosHeadShadow_;    // exits closer to vertical than this are hidden by the head (2: no cone)
    std::array<float, kConeCount> cosCone_;
    ExitAngleBins exitBin_;
    std::unique_ptr<ConvexIntersector> convex_;
    std::unique_ptr<EmbreeIntersector> embree_;
    // Collimated light on a convex stone: the entry search with its divisions done once.
    std::unique_ptr<ConvexBeamEntry> beam_;
    // Collimated light at one index of refraction: every photon entering through facet f meets it at the
    // same angle, so its Fresnel reflectance and both directions are worked out once per facet.
    struct FixedEntry {
        float reflectance;
        Vec3f reflected, refracted;
    };
    std::vector<FixedEntry> fixedEntry_;
};

}  // namespace facetlight
