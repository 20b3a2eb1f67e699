#include "study/job_request.h"

#include "sweep/sweep_request.h"
#include "util/error.h"

namespace facetlight {

JobRequest JobRequest::fromJson(const nlohmann::json& j, JobRequest spec) {
    if (!j.is_object()) throw Error("", "the job must be a JSON object");
    if (!j.contains("mesh")) throw Error("mesh", "mesh is required");
    spec.mesh = settings::readText(j["mesh"], "mesh");
    if (j.contains("name")) spec.name = settings::readText(j["name"], "name");
    nlohmann::json trace = j;
    for (const char* key : {"mesh", "name", "render", "aset", "tilt_series", "fire_picture", "sweep", "cut"})
        trace.erase(key);
    if (const auto r = j.find("render"); r != j.end()) {
        if (r->is_object()) {
            spec.settings.render = renderSettingsSchema().read(*r, "render");
        } else if (r->is_boolean()) {
            spec.settings.render = r->get<bool>() ? std::optional(RenderSettings{}) : std::nullopt;
        } else if (!r->is_null()) {
            throw Error("render", "render must be false or an object {width, height, samples, camera}");
        }
    }
    // The viewer's views (docs/physics.md): objects of their settings, each seen through the render's camera.
    if (j.contains("aset")) spec.settings.aset = AsetSettings::fromJson(j["aset"]);
    if (j.contains("tilt_series")) spec.settings.tiltSeries = TiltSeriesSettings::fromJson(j["tilt_series"]);
    if (j.contains("fire_picture"))
        spec.settings.firePicture = firePictureSettingsSchema().read(j["fire_picture"], "fire_picture");
    for (const char* view : {"aset", "tilt_series", "fire_picture"}) {
        if (j.contains(view) && !spec.settings.render)
            throw Error(view, std::string(view) + " must come with render: set render to true or an object");
    }
    traceSettingsSchema().read(spec.settings.trace, trace);
    if (const auto c = j.find("cut"); c != j.end() && !c->is_null()) {
        if (!c->is_object()) throw Error("cut", "cut must be an object of the shape's parameters");
        spec.cut.clear();
        for (const auto& [key, value] : c->items())
            spec.cut[key] = settings::readNumber(value, settings::fieldPath("cut", key), {});
        if (j.contains("sweep")) throw Error("cut", "a sweep holds parameters with sweep.set, not cut");
        try {
            completeCutValues(findCutShape(spec.mesh), spec.cut);
        } catch (const Error& e) {
            throw Error("cut", std::string("cut: ") + e.what());
        }
    }
    // A sweep of a shape of the cut library (docs/sweeps.md): every point an ordinary trace of these
    // settings.
    if (const auto s = j.find("sweep"); s != j.end() && !s->is_null()) {
        spec.settings.sweep = sweepRequestSchema().read(*s, "sweep");
        if (!s->contains("figure")) spec.settings.sweep->figures = {defaultSweepFigure(spec.settings.trace)};
        if (spec.settings.render) throw Error("render", "a sweep makes no render: set render to false");
        planSweep(spec.mesh, *spec.settings.sweep, spec.settings.trace);
    }
    return spec;
}

Stone cutStone(const JobRequest& spec) {
    return Stone::build(makeCut(spec.mesh, spec.cut), spec.name.empty() ? spec.mesh : spec.name);
}

nlohmann::json toJson(const JobRequest& spec) {
    nlohmann::json j = toJson(spec.settings.trace);
    j["mesh"] = spec.mesh;
    if (!spec.name.empty()) j["name"] = spec.name;
    j["render"] = spec.settings.render ? toJson(*spec.settings.render) : nlohmann::json(false);
    if (spec.settings.aset) j["aset"] = toJson(*spec.settings.aset);
    if (spec.settings.tiltSeries) j["tilt_series"] = toJson(*spec.settings.tiltSeries);
    if (spec.settings.firePicture) j["fire_picture"] = toJson(*spec.settings.firePicture);
    if (spec.settings.sweep) j["sweep"] = toJson(*spec.settings.sweep);
    if (!spec.cut.empty()) j["cut"] = spec.cut;
    return j;
}

}  // namespace facetlight
