#include "trace/trace_settings.h"

#include <algorithm>
#include <cmath>

#include "geometry/polygon_mesh.h"
#include "optics/material.h"
#include "util/error.h"

namespace facetlight {
namespace {

using namespace settings;

const Schema<LightSettings>& lightSchema() {
    static const Schema<LightSettings> schema({
        choice("model", &LightSettings::model, kLightModelNames, {"--light", "Light model"}),
        vec3("direction", &LightSettings::direction, true,
             {"--light-direction", "Collimated: direction of travel of the light (x y z)"}),
        number("tilt_deg", &LightSettings::tiltDeg, {.lo = -90, .hi = 90},
               {"--tilt", "Tilt of the stone about the x axis", "degrees"}),
        number("head_shadow_deg", &LightSettings::headShadowDeg, {.lo = 0, .hi = 90, .openHi = true},
               {"--head-shadow", "Hemisphere: half-angle of the viewer's cone removed", "degrees"}),
        choice("sky", &LightSettings::sky, kSkyNames,
               {"--sky", "Hemisphere: uniform (a diffuse dome, the same radiance everywhere) or cosine "
                         "(radiance falling as cos(theta) from the zenith)"}),
        vec3("position", &LightSettings::position, false,
             {"--light-position", "Point: the source position (x y z), outside the stone"}),
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

const Schema<FireSettings>& fireSchema() {
    static const Schema<FireSettings> schema({
        boolean(
            "enabled", &FireSettings::enabled,
            {"--fire", "Also trace each photon at the C, D and F lines and measure fire (stats.json: fire)"}),
        number("pupil_mm", &FireSettings::pupilMm, {.lo = 0, .hi = 20, .openLo = true},
               {"--pupil-mm", "Fire: the viewer's pupil diameter", "mm"}),
        number("distance_mm", &FireSettings::distanceMm, {.lo = 10, .hi = 100000},
               {"--viewing-distance-mm", "Fire: the distance from the eye to the stone", "mm"}),
    });
    return schema;
}

std::string materialHelp() {
    std::string help = "Material: ";
    const std::vector<std::string> names = materialNames();
    for (size_t i = 0; i < names.size(); ++i)
        help += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return help;
}

}  // namespace

const Schema<TraceSettings>& traceSettingsSchema() {
    static const Schema<TraceSettings> schema(
        {
            count("photons", &TraceSettings::photons, 1, kMaxPhotons,
                  {"--photons", "Photons to shoot, e.g. 1e6 or 1000000"}),
            count("threads", &TraceSettings::threads, 1, kMaxThreads, {"--threads", "Worker threads"}),
            count("seed", &TraceSettings::seed, 0, UINT64_MAX,
                  {"--seed", "Random seed; the same seed gives the same results"}),
            text("material", &TraceSettings::material, {"--material", materialHelp()}),
            optionalNumber("n", &TraceSettings::n, {.lo = 1, .hi = 10, .openLo = true},
                           {"--n", "A constant refractive index instead of the material's"}),
            boolean("dispersion", &TraceSettings::dispersion,
                    {"--no-dispersion", "Trace every photon at 589.3 nm"}),
            count("max_bounces", &TraceSettings::maxBounces, 1, 100000,
                  {"--max-bounces", "Internal reflections before a photon counts as trapped"}),
            choice("intersector", &TraceSettings::intersector, kIntersectorNames,
                   {"--intersector", "Ray-stone intersection"}),
            object("light", &TraceSettings::light, lightSchema()),
            object("fire", &TraceSettings::fire, fireSchema()),
        },
        // The material's name matters only without an `n` to override it.
        [](const TraceSettings& s, const std::string& path) {
            if (!s.n) readChoice(s.material, fieldPath(path, "material"), materialNames());
        });
    return schema;
}

TraceSettings TraceSettings::fromJson(const nlohmann::json& j) {
    return traceSettingsSchema().read(j);
}

nlohmann::json toJson(const TraceSettings& s) {
    return traceSettingsSchema().write(s);
}

}  // namespace facetlight
