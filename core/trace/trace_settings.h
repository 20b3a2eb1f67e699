#pragma once
// The inputs of a photon trace (after Tungsten: plain settings structs, kept apart from the algorithm), each
// setting described once in traceSettingsSchema(): JSON, checks, CLI flags and the API schema follow from it.
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/geometry.h"
#include "util/name_table.h"
#include "util/settings_schema.h"

namespace facetlight {

enum class LightModelKind { Collimated, Hemisphere, Point };
// The hemisphere's sky: uniform radiance (a diffuse dome, directions uniform in solid angle), or radiance
// falling as cos(theta) from the zenith (directions cosine-weighted: darker toward the horizon).
enum class SkyKind { Uniform, Cosine };
enum class IntersectorKind { Auto, Convex, Embree };

inline constexpr NameTable<LightModelKind, 3> kLightModelNames{{{{LightModelKind::Collimated, "collimated"},
                                                                 {LightModelKind::Hemisphere, "hemisphere"},
                                                                 {LightModelKind::Point, "point"}}}};
inline constexpr NameTable<IntersectorKind, 3> kIntersectorNames{{{{IntersectorKind::Auto, "auto"},
                                                                   {IntersectorKind::Convex, "convex"},
                                                                   {IntersectorKind::Embree, "embree"}}}};
inline constexpr NameTable<SkyKind, 2> kSkyNames{{{{SkyKind::Uniform, "uniform"}, {SkyKind::Cosine, "cosine"}}}};

struct LightSettings {
    LightModelKind model = LightModelKind::Collimated;
    Vec3 direction{0, 0, -1};  // collimated: direction of travel of the light (default straight down)
    double tiltDeg = 0;        // the stone tilted about the x axis by this angle (light rotated by -tilt)
    double headShadowDeg = 0;  // hemisphere: half-angle of the observer's cone removed around the vertical
    SkyKind sky = SkyKind::Uniform;  // hemisphere
    Vec3 position{0, 0, 10};   // point: the source position, outside the stone's bounding sphere
};

// The fire trace (trace/fire_trace.h): each photon also followed at the Fraunhofer C, D and F lines with the
// same random choices, and its red and blue exits compared against what the viewer's pupil spans.
struct FireSettings {
    bool enabled = false;
    double pupilMm = 4;       // pupil diameter
    double distanceMm = 250;  // from the eye to the stone
    // The angle the pupil spans seen from the stone: 2 atan(pupil / 2 / distance), 0.917 deg by default.
    double pupilAngleDeg() const { return degrees(2 * std::atan(pupilMm / 2 / distanceMm)); }
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
    FireSettings fire;

    // Missing keys keep their defaults; throws Error naming the field by its dotted path.
    static TraceSettings fromJson(const nlohmann::json& j);
};

constexpr uint64_t kMaxPhotons = 10'000'000'000ULL;
constexpr int kMaxThreads = 1024;

const settings::Schema<TraceSettings>& traceSettingsSchema();
nlohmann::json toJson(const TraceSettings& s);

}  // namespace facetlight
