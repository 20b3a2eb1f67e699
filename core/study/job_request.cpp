#include "study/job_request.h"

#include <map>

#include "cuts/cut_library.h"
#include "cuts/facet_design.h"
#include "sweep/sweep_request.h"
#include "util/error.h"
#include "util/name_table.h"

namespace facetlight {

namespace {

// "P 43.5": the main proportions by their letters, the others by their names ("lower half 77").
std::string changedParameters(const std::string& shape, const CutValues& values) {
    static const std::map<std::string, std::string> letters = {
        {"table", "T"}, {"crown", "C"}, {"pavilion", "P"}, {"girdle", "G"}};
    std::string text;
    if (!isLibraryShape(shape)) {  // a design's tiers: "tier:P1 41.5"
        for (const auto& [name, value] : values) text += " " + name + " " + formatNumber(value);
        return text;
    }
    for (const CutParameter& p : findCutShape(shape).parameters) {
        const auto v = values.find(p.name);
        if (v == values.end() || v->second == p.defaultValue) continue;
        const auto letter = letters.find(p.name);
        text += " " + (letter != letters.end() ? letter->second : spacedName(p.name)) + " " +
                parameterText(p, v->second);
    }
    return text;
}

}  // namespace

JobRequest JobRequest::fromJson(const nlohmann::json& j, JobRequest spec) {
    if (!j.is_object()) throw Error("", "the job must be a JSON object");
    if (!j.contains("mesh")) throw Error("mesh", "mesh is required");
    spec.mesh = settings::readText(j["mesh"], "mesh");
    if (j.contains("name")) spec.name = settings::readText(j["name"], "name");
    nlohmann::json trace = j;
    for (const char* key : {"mesh", "name", "render", "aset", "tilt_series", "fire_picture", "polariscope",
                            "doubling", "colour", "sweep", "cut"})
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
    if (j.contains("polariscope"))
        spec.settings.polariscope = polariscopeSettingsSchema().read(j["polariscope"], "polariscope");
    if (j.contains("doubling")) spec.settings.doubling = doublingSettingsSchema().read(j["doubling"], "doubling");
    if (j.contains("colour")) spec.settings.colour = colourSettingsSchema().read(j["colour"], "colour");
    traceSettingsSchema().read(spec.settings.trace, trace);
    if (const auto c = j.find("cut"); c != j.end() && !c->is_null()) {
        if (!c->is_object()) throw Error("cut", "cut must be an object of the shape's parameters");
        spec.cut.clear();
        for (const auto& [key, value] : c->items())
            spec.cut[key] = settings::readNumber(value, settings::fieldPath("cut", key), {});
        if (j.contains("sweep")) throw Error("cut", "a sweep holds parameters with sweep.set, not cut");
        // A design's tiers are checked once the service has found its file (cutStone).
        try {
            if (isLibraryShape(spec.mesh)) completeCutValues(findCutShape(spec.mesh), spec.cut);
        } catch (const Error& e) {
            throw e.within("cut");
        }
    }
    // A sweep (docs/sweeps.md): every point an ordinary trace of these settings. A shape of the cut library is
    // checked here; a design or mesh file once the service has found it (never a path from a job).
    if (const auto s = j.find("sweep"); s != j.end() && !s->is_null()) {
        spec.settings.sweep = sweepRequestSchema().read(*s, "sweep");
        if (!s->contains("figure")) spec.settings.sweep->figures = {defaultSweepFigure(spec.settings.trace)};
        if (spec.settings.render) throw Error("render", "a sweep makes no render: set render to false");
        if (isLibraryShape(spec.mesh))
            planSweep(spec.mesh, *spec.settings.sweep, spec.settings.trace, spec.settings.colour);
    }
    return spec;
}

Stone cutStone(const JobRequest& spec, const std::string& source) {
    const std::string name = spec.name.empty() ? spec.mesh : spec.name;
    if (isLibraryShape(source)) return Stone::build(makeCut(source, spec.cut), name);
    const std::shared_ptr<const FileShape> file = fileShape(source);
    if (!file->design) throw Error("cut", "cut applies to a shape of the cut library or a GemCad design's tiers");
    CutValues values;
    try {
        values = completeCutValues(file->shape, spec.cut);
    } catch (const Error& e) {
        throw e.within("cut");
    }
    return Stone::build(file->shape.build(values), name);
}

std::string defaultJobName(const JobRequest& spec, const std::string& design) {
    if (!spec.settings.sweep)
        return design + (spec.cut.empty() ? "" : changedParameters(spec.mesh, spec.cut));
    const SweepRequest& sweep = *spec.settings.sweep;
    std::string varied;
    for (const SweepAxis& axis : sweep.axes) varied += (varied.empty() ? "" : " × ") + spacedName(axis.name);
    return design + changedParameters(spec.mesh, sweep.set) + ", sweep of " + varied;
}

nlohmann::json toJson(const JobRequest& spec) {
    nlohmann::json j = toJson(spec.settings.trace);
    j["mesh"] = spec.mesh;
    if (!spec.name.empty()) j["name"] = spec.name;
    j["render"] = spec.settings.render ? toJson(*spec.settings.render) : nlohmann::json(false);
    if (spec.settings.aset) j["aset"] = toJson(*spec.settings.aset);
    if (spec.settings.tiltSeries) j["tilt_series"] = toJson(*spec.settings.tiltSeries);
    if (spec.settings.firePicture) j["fire_picture"] = toJson(*spec.settings.firePicture);
    if (spec.settings.polariscope) j["polariscope"] = polariscopeSettingsSchema().write(*spec.settings.polariscope);
    if (spec.settings.doubling) j["doubling"] = doublingSettingsSchema().write(*spec.settings.doubling);
    if (spec.settings.colour) j["colour"] = colourSettingsSchema().write(*spec.settings.colour);
    if (spec.settings.sweep) j["sweep"] = toJson(*spec.settings.sweep);
    if (!spec.cut.empty()) j["cut"] = spec.cut;
    return j;
}

}  // namespace facetlight
