#include "optics/light_settings.h"

#include <algorithm>
#include <cmath>

#include "geometry/polygon_mesh.h"
#include "util/error.h"

namespace facetlight {

using namespace settings;

const Schema<LightSettings>& lightSettingsSchema() {
    static const Schema<LightSettings> schema(
        {
            choice("model", &LightSettings::model, kLightModelNames, {"--light", "Light model"}),
            vec3("direction", &LightSettings::direction, true,
                 {"--light-direction", "Collimated: direction of travel of the light (x y z)"}),
            number("tilt_deg", &LightSettings::tiltDeg, {.lo = -90, .hi = 90},
                   {"--stone-tilt",
                    "Tilt of the stone about the x axis, the light kept still (--tilt-series rocks it in an "
                    "animation instead)",
                    "degrees", "--tilt"}),
            number("head_shadow_deg", &LightSettings::headShadowDeg, {.lo = 0, .hi = 90, .openHi = true},
                   {"--head-shadow", "Hemisphere: half-angle of the viewer's cone removed", "degrees"}),
            choice("sky", &LightSettings::sky, kSkyNames,
                   {"--sky",
                    "Hemisphere: uniform (a diffuse dome, the same radiance everywhere) or cosine "
                    "(radiance falling as cos(theta) from the zenith)"}),
            vec3("position", &LightSettings::position, false,
                 {"--light-position", "Point: the source position (x y z), outside the stone"}),
            optionalNumber("polarizer_deg", &LightSettings::polarizerDeg,
                           {.lo = 0, .hi = 180, .openHi = true},
                           {"--polarizer",
                            "A linear polariser over the light, its axis this far from the stone's x axis "
                            "(not with --polarization off)",
                            "degrees"}),
        },
        // No stone reaches beyond kMaxMeshCoordinate (a light at 1e308 "succeeded" with no photon hitting);
        // LightModel also refuses a light too far for its stone.
        [](const LightSettings& s, const std::string& path) {
            const Vec3& p = s.position;
            if (std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) > kMaxMeshCoordinate) {
                const std::string field = fieldPath(path, "position");
                throw Error(field, field + " must be finite, each coordinate within 1e9");
            }
        });
    return schema;
}

}  // namespace facetlight
