#include "study/study_spec.h"

#include "util/error.h"

namespace facetlight {

StudySpec StudySpec::fromJson(const nlohmann::json& j, StudySpec spec) {
    if (!j.is_object()) throw Error("", "the job must be a JSON object");
    if (!j.contains("mesh")) throw Error("mesh", "mesh is required");
    spec.mesh = settings::readText(j["mesh"], "mesh");
    if (j.contains("name")) spec.name = settings::readText(j["name"], "name");
    nlohmann::json trace = j;
    for (const char* key : {"mesh", "name", "render", "aset", "tilt_series", "fire_picture"})
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
    return spec;
}

nlohmann::json toJson(const StudySpec& spec) {
    nlohmann::json j = toJson(spec.settings.trace);
    j["mesh"] = spec.mesh;
    if (!spec.name.empty()) j["name"] = spec.name;
    j["render"] = spec.settings.render ? toJson(*spec.settings.render) : nlohmann::json(false);
    if (spec.settings.aset) j["aset"] = toJson(*spec.settings.aset);
    if (spec.settings.tiltSeries) j["tilt_series"] = toJson(*spec.settings.tiltSeries);
    if (spec.settings.firePicture) j["fire_picture"] = toJson(*spec.settings.firePicture);
    return j;
}

}  // namespace facetlight
