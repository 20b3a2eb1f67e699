#include "scene/scene.h"

#include <algorithm>
#include <cmath>

#include "intersect/convex_intersector.h"
#include "intersect/embree_intersector.h"
#include "util/error.h"

namespace facetlight {
namespace {

double smoothstep(double lo, double hi, double x) {
    const double t = std::clamp((x - lo) / (hi - lo), 0.0, 1.0);
    return t * t * (3 - 2 * t);
}

}  // namespace

std::optional<MaterialChoice> namedMaterial(const SceneSettings& settings) {
    if (settings.constantIndex) return MaterialChoice{Material::constant(*settings.constantIndex), "n"};
    if (settings.customMaterial)
        return MaterialChoice{Material::defined(*settings.customMaterial), "custom_material"};
    if (settings.material != "auto") return MaterialChoice{Material::byName(settings.material), "material"};
    return std::nullopt;
}

Optic chosenOptic(const SceneSettings& settings) {
    const std::optional<MaterialChoice> named = namedMaterial(settings);
    return named ? named->material.optic() : Optic::Isotropic;
}

std::string chosenMaterialName(const SceneSettings& settings) {
    if (settings.constantIndex) return "a constant n";
    return settings.customMaterial ? settings.customMaterial->name : settings.material;
}

MaterialChoice chooseMaterial(const SceneSettings& settings, const Stone& stone) {
    MaterialChoice choice = [&] {
        if (std::optional<MaterialChoice> named = namedMaterial(settings)) return *std::move(named);
        if (stone.design && stone.design->refractiveIndex)
            return MaterialChoice{Material::constant(*stone.design->refractiveIndex, "design file index"),
                                  "design file"};
        return MaterialChoice{Material::byName("diamond"), "default"};
    }();
    // A job's table replaces the material's own spectrum (docs/optics.md, "Coloured materials").
    if (settings.absorption) choice.material = choice.material.withAbsorption(settings.absorption);
    return choice;
}

Scene::Scene(const Stone& stone, const SceneSettings& settings)
    : stone_(stone),
      materialChoice_(chooseMaterial(settings, stone)),
      material_(materialChoice_.material),
      lightSettings_(settings.light),
      light_(settings.light, stone),
      fixedIndex_(float(material_.indexD())) {
    if (stone.facets.empty()) throw Error("stone '" + stone.name + "' has no facets");
    dispersive_ = settings.dispersion && material_.dispersive();
    for (const Facet& f : stone.facets) normal_.emplace_back(f.normal);
    cosTilt_ = std::cos(radians(settings.light.tiltDeg));
    sinTilt_ = std::sin(radians(settings.light.tiltDeg));
    vertical_ = toStone({0, 0, 1});
    center_ = stone.bounds.center();
    const Vec3 extent = stone.bounds.extent();
    diameter_ = stone.proportions.diameter > 0 ? stone.proportions.diameter : std::max(extent.x, extent.y);
    floorHeight_ = INFINITY;
    for (const Vec3& v : stone.vertices) floorHeight_ = std::min(floorHeight_, dot(vertical_, v));

    lightDir_ = toStone(normalize(settings.light.direction));
    lightPos_ = toStone(settings.light.position);
    const Vec3 toCenter = light_.sphereCenter() - lightPos_;
    pointIntensity_ = dot(toCenter, toCenter);  // irradiance 1 at the centre
    cosShadow3_ = std::pow(std::cos(radians(settings.light.headShadowDeg)), 3);

    IntersectorKind kind = settings.intersector;
    if (kind == IntersectorKind::Auto)
        kind = stone.convex ? IntersectorKind::Convex : IntersectorKind::Embree;
    if (kind == IntersectorKind::Convex) {
        if (!stone.convex)
            throw Error("intersector 'convex' needs a convex stone; '" + stone.name + "' is not");
        convex_ = std::make_unique<ConvexIntersector>(stone);
        if (light_.collimated()) beam_ = std::make_unique<ConvexBeamEntry>(stone, Vec3f(light_.direction()));
    } else {
        embree_ = std::make_unique<EmbreeIntersector>(stone);
    }
}

Scene::~Scene() = default;

Vec3 Scene::toStone(const Vec3& v) const {
    return {v.x, v.y * cosTilt_ + v.z * sinTilt_, -v.y * sinTilt_ + v.z * cosTilt_};
}

Vec3 Scene::toWorld(const Vec3& v) const {
    return {v.x, v.y * cosTilt_ - v.z * sinTilt_, v.y * sinTilt_ + v.z * cosTilt_};
}

bool Scene::enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const {
    return convex_ ? convex_->enter(origin, dir, hit) : embree_->enter(origin, dir, hit);
}

bool Scene::leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const {
    return convex_ ? convex_->leave(origin, dir, hit) : embree_->leave(origin, dir, hit);
}

bool Scene::hitFloor(const Vec3& origin, const Vec3& dir, double& t) const {
    const double down = dot(vertical_, dir);
    if (!(down < -1e-9)) return false;
    t = (floorHeight_ - dot(vertical_, origin)) / down;
    return t > 0;
}

double Scene::directIrradiance(const Vec3& p, Rng& rng) const {
    const Vec3 origin = p + vertical_ * (1e-4 * diameter_);
    SurfaceHit hit;
    switch (lightSettings_.model) {
        case LightModelKind::Collimated: {
            const double cosTheta = -dot(lightDir_, vertical_);
            if (cosTheta <= 0 || enter(Vec3f(origin), Vec3f(-lightDir_), hit)) return 0;
            return cosTheta;
        }
        case LightModelKind::Hemisphere: {
            // Sky radiance L0 cos(theta) outside the head cone: the light model's cosine-weighted photons.
            // Irradiance is 1 in the open; shadow rays drawn with density cos^2(theta), stratified in
            // azimuth, estimate the share the stone hides.
            constexpr int kRays = 8;
            int open = 0;
            for (int i = 0; i < kRays; ++i) {
                const double cosTheta = std::cbrt(rng.uniformDouble() * cosShadow3_);
                const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
                const double phi = 2 * kPi * (i + rng.uniformDouble()) / kRays;
                const Vec3 toSky = toStone({sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta});
                open += !enter(Vec3f(origin), Vec3f(toSky), hit);
            }
            return double(open) / kRays;
        }
        case LightModelKind::Point: {
            const Vec3 toLight = lightPos_ - origin;
            const double d2 = dot(toLight, toLight), d = std::sqrt(d2);
            const Vec3 dir = toLight / d;
            const double cosTheta = dot(dir, vertical_);
            if (cosTheta <= 0 || (enter(Vec3f(origin), Vec3f(dir), hit) && hit.t < d)) return 0;
            return pointIntensity_ * cosTheta / d2;
        }
    }
    return 0;
}

double Scene::photonPower(uint64_t count) const {
    const double n = double(std::max<uint64_t>(count, 1));
    const double r = light_.sphereRadius();
    switch (lightSettings_.model) {
        case LightModelKind::Collimated:
            return kPi * light_.discRadius() * light_.discRadius() / n;
        case LightModelKind::Hemisphere: {
            // Flux L0 pi r^2 * pi cos^2(s) through the sphere's cross-section, with L0 = 3 / (2 pi cos^3 s)
            // making the open floor's irradiance 1.
            return 3 * kPi * r * r / (2 * std::cos(radians(lightSettings_.headShadowDeg))) / n;
        }
        case LightModelKind::Point: {
            const double d2 = pointIntensity_;
            const double cosCone = std::sqrt(std::max(0.0, 1 - r * r / d2));
            return pointIntensity_ * 2 * kPi * (1 - cosCone) / n;
        }
    }
    return 0;
}

bool Scene::landOnFloor(const Vec3f& exitPosition, const Vec3f& exitDirection, Vec3& position) const {
    const Vec3 o{exitPosition.x, exitPosition.y, exitPosition.z};
    const Vec3 d{exitDirection.x, exitDirection.y, exitDirection.z};
    double t;
    if (!hitFloor(o, d, t)) return false;
    // A convex stone is never met again; another shape may catch the photon (not followed further).
    SurfaceHit hit;
    if (!convex_ && enter(Vec3f(o + d * (1e-5 * diameter_)), Vec3f(d), hit)) return false;
    position = o + d * t;
    return true;
}

double Scene::environment(const Vec3& dir, const Vec3& toViewer) {
    if (dir.z < 0) return 0.03 * (1 + dir.z);  // dark below the horizon
    const double elevation = degrees(std::asin(std::min(1.0, dir.z)));
    const double azimuth = degrees(std::atan2(dir.y, dir.x));
    // Six soft boxes around the stone between 20 and 65 degrees elevation, 40 degrees wide, 2 degree soft
    // edges; a dim studio between them.
    const double fromCentre = std::fabs(std::remainder(azimuth - 30, 60.0));
    const double panel =
        smoothstep(22, 18, fromCentre) * smoothstep(18, 22, elevation) * smoothstep(67, 63, elevation);
    // An overhead ring light just outside the viewer's head.
    const double ring = smoothstep(68, 71, elevation) * smoothstep(80, 77, elevation);
    const double studio = 0.05 + 0.1 * dir.z + 3.0 * panel + 1.5 * ring;
    const double fromViewer = degrees(std::acos(std::clamp(dot(dir, toViewer), -1.0, 1.0)));
    return studio * (0.02 + 0.98 * smoothstep(9, 12, fromViewer));
}

}  // namespace facetlight
