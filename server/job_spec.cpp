#include "job_spec.h"

#include "util/error.h"
#include "util/json_fields.h"

namespace facetlight::server {

namespace {

void checkRenderLimits(const JobSpec& spec, const ServiceLimits& limits) {
    const auto& r = spec.settings.render;
    if (!r) return;
    const std::string maxPhotons = std::to_string(limits.maxPhotons);
    const std::string side = std::to_string(limits.maxImageSide);
    if (r->width > limits.maxImageSide)
        throw Error("render.width must be at most " + side + " on this server");
    if (r->height > limits.maxImageSide) {
        throw Error("render.height must be at most " + side + " on this server");
    }
    if (r->mapPhotons > limits.maxPhotons) {
        throw Error("render.map_photons must be at most " + maxPhotons + " on this server");
    }
}

}  // namespace

JobSpec parseJobSpec(const nlohmann::json& body, int defaultThreads, const ServiceLimits* limits) {
    if (!body.is_object()) throw Error("the job must be a JSON object");
    JobSpec spec;
    nlohmann::json trace = body;
    if (!body.contains("mesh")) throw Error("mesh is required");
    if (!body["mesh"].is_string()) throw Error("mesh must be a string");
    spec.mesh = body["mesh"].get<std::string>();
    trace.erase("mesh");
    if (!body.contains("photons")) throw Error("photons is required");
    // This server's cap, not only the core's, names the range a user may ask for.
    if (limits) json_fields::getCount(body["photons"], "photons", 1, limits->maxPhotons);
    if (!body.contains("threads")) trace["threads"] = defaultThreads;
    if (body.contains("render")) {
        const nlohmann::json& r = body["render"];
        if (r.is_object()) {
            spec.settings.render = RenderSettings::fromJson(r);
        } else if (r.is_boolean()) {
            if (r.get<bool>()) spec.settings.render = RenderSettings{};
        } else if (!r.is_null()) {
            throw Error("render must be false or an object {width, height, samples, camera}");
        }
        trace.erase("render");
    }
    // The viewer's views (docs/physics.md): objects of their settings, each asking for a render too.
    if (body.contains("aset")) {
        spec.settings.aset = AsetSettings::fromJson(body["aset"]);
        trace.erase("aset");
    }
    if (body.contains("tilt_series")) {
        spec.settings.tiltSeries = TiltSeriesSettings::fromJson(body["tilt_series"]);
        trace.erase("tilt_series");
    }
    if ((spec.settings.aset || spec.settings.tiltSeries) && !spec.settings.render) {
        throw Error(std::string(spec.settings.aset ? "aset" : "tilt_series") +
                    " must come with render: set render to true or an object");
    }
    spec.settings.trace = TraceSettings::fromJson(trace);
    if (limits) checkRenderLimits(spec, *limits);
    return spec;
}
nlohmann::json toJson(const JobSpec& spec) {
    nlohmann::json j = toJson(spec.settings.trace);
    j["mesh"] = spec.mesh;
    j["render"] = spec.settings.render ? toJson(*spec.settings.render) : nlohmann::json(false);
    if (spec.settings.aset) j["aset"] = toJson(*spec.settings.aset);
    if (spec.settings.tiltSeries) j["tilt_series"] = toJson(*spec.settings.tiltSeries);
    return j;
}

}  // namespace facetlight::server
