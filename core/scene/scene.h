#pragma once
// The world every phase of a study sees, prepared once per study (after Tungsten: one scene shared by every
// phase): the stone with its one intersector (convex or Embree), the material and the light model; and, for
// the renderer, the stone above a diffuse floor inside a studio environment (soft light panels above, dark
// below, the viewer's own dark silhouette above the stone: the contrast that makes a diamond sparkle). It
// knows nothing of the tracer: the statistics trace, the photon pass and the renderer each prepare what they
// need from it (trace/trace_base.h for the tracer).
//
// Geometry is kept in the stone's frame: a tilted stone is the world rotated by -tilt about x. The floor is
// horizontal in the world, under the stone's lowest point.
#include <memory>
#include <optional>
#include <vector>

#include "geometry/geometry.h"
#include "geometry/ray.h"
#include "optics/light_model.h"
#include "optics/material.h"
#include "scene/scene_settings.h"
#include "stone/stone.h"
#include "util/random.h"

namespace facetlight {

// The material a job traces and where it came from: "n" (a constant index), "custom_material" (the job
// defines its own), "material" (the job names one), "design file" (the stone's file states its index and the
// job's material is "auto") or "default" (diamond).
struct MaterialChoice {
    Material material;
    std::string source;
};
MaterialChoice chooseMaterial(const SceneSettings& settings, const Stone& stone);
// The material the settings name before a stone is known, in the one order of precedence: `n`, the job's
// own material, a named one; none for "auto" (then the design file's index or the default decides).
std::optional<MaterialChoice> namedMaterial(const SceneSettings& settings);
// The optic class of the material the settings choose, before a stone is known: "auto" and `n` are
// singly refracting (a design file states one index).
Optic chosenOptic(const SceneSettings& settings);
// The material the settings choose, named for a message before a stone is known: "a constant n", the job's
// own material's name, or the material's ("auto" when the design file or the default decides).
std::string chosenMaterialName(const SceneSettings& settings);

class ConvexBeamEntry;
class ConvexIntersector;
class EmbreeIntersector;

class Scene {
  public:
    // Validates the settings once. Throws Error for settings that cannot be traced on this stone (e.g.
    // intersector "convex" on a non-convex stone). The stone must outlive the scene.
    Scene(const Stone& stone, const SceneSettings& settings);
    ~Scene();
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    const Stone& stone() const { return stone_; }
    const Material& material() const { return material_; }
    const std::string& materialSource() const { return materialChoice_.source; }
    const LightModel& light() const { return light_; }
    const LightSettings& lightSettings() const { return lightSettings_; }
    bool usesEmbree() const { return embree_ != nullptr; }
    // The one intersector of the stone: convex() when it is convex (and not sent to Embree), else embree().
    const ConvexIntersector* convex() const { return convex_.get(); }
    const EmbreeIntersector* embree() const { return embree_.get(); }
    // Collimated light on a convex stone: the entry search with its divisions done once; else null.
    const ConvexBeamEntry* beamEntry() const { return beam_.get(); }

    Vec3 toWorld(const Vec3& v) const;
    Vec3 toStone(const Vec3& v) const;
    const Vec3& up() const { return vertical_; }    // the world's vertical, in the stone's frame
    const Vec3& center() const { return center_; }  // of the stone's bounds, stone frame
    double diameter() const { return diameter_; }   // girdle diameter (or width): the camera's unit

    // Ray casts against the stone (see ConvexIntersector for the contracts).
    bool enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    bool leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const;
    const Vec3f& normal(uint32_t facet) const { return normal_[facet]; }
    const std::vector<Vec3f>& normals() const { return normal_; }
    double refractiveIndex(double wavelengthNm) const { return material_.index(wavelengthNm); }
    // The index at 589.3 nm, in float: every ray's when the scene is not dispersive.
    float fixedIndex() const { return fixedIndex_; }
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
    // Where light that left the stone (or was reflected off it) at `exitPosition` along `exitDirection` lands
    // on the floor; false when it goes up, or would meet the stone again.
    bool landOnFloor(const Vec3f& exitPosition, const Vec3f& exitDirection, Vec3& position) const;

    // Radiance of the studio along world direction `dir`; `toViewer` is the world direction from the stone
    // to the camera, whose surroundings are dark (the observer's head and the camera).
    static double environment(const Vec3& dir, const Vec3& toViewer);

  private:
    const Stone& stone_;
    MaterialChoice materialChoice_;
    Material material_;
    LightSettings lightSettings_;
    LightModel light_;
    bool dispersive_ = false;
    float fixedIndex_;
    std::vector<Vec3f> normal_;
    double cosTilt_ = 1, sinTilt_ = 0;
    Vec3 vertical_, center_;
    double diameter_ = 1;
    double floorHeight_ = 0;  // dot(up, p) on the floor
    Vec3 lightDir_;           // collimated: direction of travel, stone frame
    Vec3 lightPos_;           // point: stone frame
    double pointIntensity_ = 0;
    double cosShadow3_ = 1;  // hemisphere: cos^3 of the head-shadow half-angle
    std::unique_ptr<ConvexIntersector> convex_;
    std::unique_ptr<EmbreeIntersector> embree_;
    std::unique_ptr<ConvexBeamEntry> beam_;
};

}  // namespace facetlight
