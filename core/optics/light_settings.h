#pragma once
// Where a job's light comes from (after Tungsten: plain settings, apart from the light model that uses them),
// each setting described once in lightSettingsSchema().
#include <optional>

#include "geometry/geometry.h"
#include "settings/settings_schema.h"
#include "util/name_table.h"

namespace facetlight {

enum class LightModelKind { Collimated, Hemisphere, Point };
// The hemisphere's sky: uniform radiance (a diffuse dome, directions uniform in solid angle), or radiance
// falling as cos(theta) from the zenith (directions cosine-weighted: darker toward the horizon).
enum class SkyKind { Uniform, Cosine };

inline constexpr NameTable<LightModelKind, 3> kLightModelNames{{{{LightModelKind::Collimated, "collimated"},
                                                                 {LightModelKind::Hemisphere, "hemisphere"},
                                                                 {LightModelKind::Point, "point"}}}};
inline constexpr NameTable<SkyKind, 2> kSkyNames{
    {{{SkyKind::Uniform, "uniform"}, {SkyKind::Cosine, "cosine"}}}};

struct LightSettings {
    LightModelKind model = LightModelKind::Collimated;
    Vec3 direction{0, 0, -1};  // collimated: direction of travel of the light (default straight down)
    double tiltDeg = 0;        // the stone tilted about the x axis by this angle (light rotated by -tilt)
    double headShadowDeg = 0;  // hemisphere: half-angle of the observer's cone removed around the vertical
    SkyKind sky = SkyKind::Uniform;  // hemisphere
    Vec3 position{0, 0, 10};         // point: the source position, outside the stone's bounding sphere
    // A linear polariser over the light: its axis in the horizontal plane at this angle from the stone's x
    // axis toward its y (a polariscope's lower filter). None: unpolarised light. Needs polarised tracing.
    std::optional<double> polarizerDeg;
};

// The table of LightSettings' fields (JSON key "light" of a job).
const settings::Schema<LightSettings>& lightSettingsSchema();

}  // namespace facetlight
