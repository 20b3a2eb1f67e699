#include "trace/trace_settings.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "geometry/polygon_mesh.h"
#include "optics/material.h"
#include "util/error.h"
#include "util/json_fields.h"

namespace facetlight {
namespace {

using nlohmann::json;
using namespace json_fields;

json vec3Json(const Vec3& v) {
    return json::array({v.x, v.y, v.z});
}

}  // namespace

std::string_view lightModelName(LightModelKind kind) {
    switch (kind) {
        case LightModelKind::Collimated:
            return "collimated";
        case LightModelKind::Hemisphere:
            return "hemisphere";
        case LightModelKind::Point:
            return "point";
    }
    return "collimated";
}

LightModelKind parseLightModel(std::string_view name) {
    for (LightModelKind k : {LightModelKind::Collimated, LightModelKind::Hemisphere, LightModelKind::Point}) {
        if (lightModelName(k) == name) return k;
    }
    throw Error("light.model must be one of collimated, hemisphere, point (got '" + std::string(name) + "')");
}

std::string_view intersectorName(IntersectorKind kind) {
    switch (kind) {
        case IntersectorKind::Auto:
            return "auto";
        case IntersectorKind::Convex:
            return "convex";
        case IntersectorKind::Embree:
            return "embree";
    }
    return "auto";
}

IntersectorKind parseIntersector(std::string_view name) {
    for (IntersectorKind k : {IntersectorKind::Auto, IntersectorKind::Convex, IntersectorKind::Embree}) {
        if (intersectorName(k) == name) return k;
    }
    throw Error("intersector must be one of auto, convex, embree (got '" + std::string(name) + "')");
}

void TraceSettings::validate() const {
    if (photons < 1 || photons > kMaxPhotons) throw Error("photons must be between 1 and 1e10");
    if (threads < 1 || threads > kMaxThreads) {
        throw Error("threads must be between 1 and " + std::to_string(kMaxThreads));
    }
    if (maxBounces < 1 || maxBounces > 100000) throw Error("max_bounces must be between 1 and 100000");
    if (n) {
        if (!(*n > 1 && *n <= 10)) throw Error("n must be greater than 1 and at most 10");
    } else {
        Material::byName(material);
    }
    if (!isFinite(light.direction) || length(light.direction) < 1e-12) {
        throw Error("light.direction must be a finite, non-zero vector");
    }
    if (!(std::fabs(light.tiltDeg) <= 90)) throw Error("light.tilt_deg must be between -90 and 90");
    if (!(light.headShadowDeg >= 0 && light.headShadowDeg < 90)) {
        throw Error("light.head_shadow_deg must be at least 0 and below 90");
    }
    // No stone reaches beyond kMaxMeshCoordinate; LightModel refuses a light too far for its stone.
    const Vec3& p = light.position;
    if (!isFinite(p) || std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}) > kMaxMeshCoordinate)
        throw Error("light.position must be finite, each coordinate within 1e9");
}

json toJson(const LightSettings& s) {
    return {{"model", lightModelName(s.model)},
            {"direction", vec3Json(s.direction)},
            {"tilt_deg", s.tiltDeg},
            {"head_shadow_deg", s.headShadowDeg},
            {"position", vec3Json(s.position)}};
}

json toJson(const TraceSettings& s) {
    return {{"photons", s.photons},
            {"threads", s.threads},
            {"seed", s.seed},
            {"material", s.material},
            {"n", s.n ? json(*s.n) : json(nullptr)},
            {"dispersion", s.dispersion},
            {"max_bounces", s.maxBounces},
            {"intersector", intersectorName(s.intersector)},
            {"light", toJson(s.light)}};
}

TraceSettings TraceSettings::fromJson(const json& j) {
    checkKeys(
        j, "",
        {"photons", "threads", "seed", "material", "n", "dispersion", "max_bounces", "intersector", "light"});
    TraceSettings s;
    if (j.contains("photons")) s.photons = getCount(j["photons"], "photons", 1, kMaxPhotons);
    if (j.contains("threads")) s.threads = int(getCount(j["threads"], "threads", 1, kMaxThreads));
    if (j.contains("seed")) s.seed = getCount(j["seed"], "seed", 0, UINT64_MAX);
    if (j.contains("material")) s.material = getString(j["material"], "material");
    if (j.contains("n") && !j["n"].is_null()) s.n = getNumber(j["n"], "n");
    if (j.contains("dispersion")) s.dispersion = getBool(j["dispersion"], "dispersion");
    if (j.contains("max_bounces")) s.maxBounces = int(getCount(j["max_bounces"], "max_bounces", 1, 100000));
    if (j.contains("intersector"))
        s.intersector = parseIntersector(getString(j["intersector"], "intersector"));
    if (j.contains("light")) {
        const json& l = j["light"];
        checkKeys(l, "light", {"model", "direction", "tilt_deg", "head_shadow_deg", "position"});
        if (l.contains("model")) s.light.model = parseLightModel(getString(l["model"], "light.model"));
        if (l.contains("direction")) s.light.direction = getVec3(l["direction"], "light.direction");
        if (l.contains("tilt_deg")) s.light.tiltDeg = getNumber(l["tilt_deg"], "light.tilt_deg");
        if (l.contains("head_shadow_deg")) {
            s.light.headShadowDeg = getNumber(l["head_shadow_deg"], "light.head_shadow_deg");
        }
        if (l.contains("position")) s.light.position = getVec3(l["position"], "light.position");
    }
    s.validate();
    return s;
}

}  // namespace facetlight
