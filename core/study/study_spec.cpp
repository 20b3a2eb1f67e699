#include "study/study_spec.h"

#include "util/error.h"

namespace facetlight {

StudySpec StudySpec::fromJson(const nlohmann::json& j, StudySpec spec) {
    if (!j.is_object()) throw Error("", "the job must be a JSON object");
    if (!j.contains("mesh")) throw Error("mesh", "mesh is required");
    spec.mesh = settings::readText(j["mesh"], "mesh");
    if (j.contains("name")) spec.name = settings::readText(j["name"], "name");
    nlohmann::json trace = j;
    for (const char* key : {"mesh", "name", "render"}) trace.erase(key);
    if (const auto r = j.find("render"); r != j.end()) {
        if (r->is_object()) {
            spec.settings.render = renderSettingsSchema().read(*r, "render");
        } else if (r->is_boolean()) {
            spec.settings.render = r->get<bool>() ? std::optional(RenderSettings{}) : std::nullopt;
        } else if (!r->is_null()) {
            throw Error("render", "render must be false or an object {width, height, samples, camera}");
        }
    }
    traceSettingsSchema().read(spec.settings.trace, trace);
    return spec;
}

nlohmann::json toJson(const StudySpec& spec) {
    nlohmann::json j = toJson(spec.settings.trace);
    j["mesh"] = spec.mesh;
    if (!spec.name.empty()) j["name"] = spec.name;
    j["render"] = spec.settings.render ? toJson(*spec.settings.render) : nlohmann::json(false);
    return j;
}

}  // namespace facetlight
