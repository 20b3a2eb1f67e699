#pragma once
// The inputs of a photon trace (after Tungsten: plain settings structs with JSON read/write, kept apart from
// the algorithm). fromJson() is strict, since the server feeds it untrusted job JSON: unknown keys, wrong
// types and out-of-range values throw Error naming the field.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/geometry.h"

namespace facetlight {

enum class LightModelKind { Collimated, Hemisphere, Point };
// The hemisphere's sky: uniform radiance (a diffuse dome, directions uniform in solid angle), or radiance
// falling as cos(theta) from the zenith (directions cosine-weighted: darker toward the horizon).
enum class SkyKind { Uniform, Cosine };
enum class IntersectorKind { Auto, Convex, Embree };

struct LightSettings {
    LightModelKind model = LightModelKind::Collimated;
    Vec3 direction{0, 0, -1};  // collimated: direction of travel of the light (default straight down)
    double tiltDeg = 0;        // the stone tilted about the x axis by this angle (light rotated by -tilt)
    double headShadowDeg = 0;  // hemisphere: half-angle of the observer's cone removed around the vertical
    SkyKind sky = SkyKind::Uniform;  // hemisphere
    Vec3 position{0, 0, 10};   // point: the source position, outside the stone's bounding sphere
};

struct TraceSettings {
    uint64_t photons = 1'000'000;
    int threads = 1;
    uint64_t seed = 1;
    std::string material = "diamond";
    std::optional<double> n;  // overrides the material with a constant index
    bool dispersion = true;   // each photon a wavelength in 380-780 nm; false: 589.3 nm
    int maxBounces = 512;     // internal reflections after which a photon counts as trapped (docs/optics.md)
    IntersectorKind intersector = IntersectorKind::Auto;
    LightSettings light;

    // Throws Error naming the first field out of range.
    void validate() const;
    // Missing keys keep their defaults; the result is validated.
    static TraceSettings fromJson(const nlohmann::json& j);
};

constexpr uint64_t kMaxPhotons = 10'000'000'000ULL;
constexpr int kMaxThreads = 1024;

std::string_view lightModelName(LightModelKind kind);
LightModelKind parseLightModel(std::string_view name);  // throws Error
std::string_view skyName(SkyKind kind);
SkyKind parseSky(std::string_view name);  // throws Error
std::string_view intersectorName(IntersectorKind kind);
IntersectorKind parseIntersector(std::string_view name);  // throws Error

nlohmann::json toJson(const LightSettings& s);
nlohmann::json toJson(const TraceSettings& s);

}  // namespace facetlight
