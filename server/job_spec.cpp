#include "job_spec.h"

#include "util/error.h"

namespace facetlight::server {

namespace {

void checkRenderLimits(const JobRequest& spec, const ServiceLimits& limits) {
    const auto& r = spec.settings.render;
    if (!r) return;
    const std::string side = std::to_string(limits.maxImageSide);
    if (r->width > limits.maxImageSide)
        throw Error("render.width", "render.width must be at most " + side + " on this server");
    if (r->height > limits.maxImageSide)
        throw Error("render.height", "render.height must be at most " + side + " on this server");
    if (r->mapPhotons > limits.maxPhotons) {
        throw Error("render.map_photons", "render.map_photons must be at most " +
                                              std::to_string(limits.maxPhotons) + " on this server");
    }
}

// What a job leaves out: core's defaults, but every core of the machine unless it asks for fewer.
JobRequest serviceDefaults(int defaultThreads) {
    JobRequest defaults;
    defaults.settings.trace.threads = defaultThreads;
    return defaults;
}

}  // namespace

JobRequest parseJobSpec(const nlohmann::json& body, int defaultThreads, const ServiceLimits* limits) {
    // This server's cap, not only the core's, names the range a user may ask for.
    if (limits && body.is_object() && body.contains("photons"))
        settings::readCount(body["photons"], "photons", 1, limits->maxPhotons);
    const JobRequest spec = JobRequest::fromJson(body, serviceDefaults(defaultThreads));
    if (!body.contains("photons")) throw Error("photons", "photons is required");
    if (limits) checkRenderLimits(spec, *limits);
    if (limits && spec.settings.sweep) {
        uint64_t points = 1;
        for (const SweepAxis& axis : spec.settings.sweep->axes) points *= axis.size();
        if (spec.settings.trace.photons > limits->maxPhotons / points)
            throw Error("photons", "a sweep traces photons at each of its " + std::to_string(points) +
                                       " points: photons times points must be at most " +
                                       std::to_string(limits->maxPhotons) + " on this server");
    }
    return spec;
}

nlohmann::json jobDefaults(int defaultThreads) {
    JobRequest spec = serviceDefaults(defaultThreads);
    spec.settings.render = RenderSettings{};
    spec.settings.aset = AsetSettings{};
    spec.settings.tiltSeries = TiltSeriesSettings{};
    spec.settings.firePicture = FirePictureSettings{};
    spec.settings.colour = ColourSettings{};
    nlohmann::json j = toJson(spec);
    j.erase("mesh");
    return j;
}

JobRequest storedJobSpec(const nlohmann::json& request) {
    return JobRequest::fromJson(request);
}

}  // namespace facetlight::server
