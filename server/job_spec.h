#pragma once
// What a client may ask of the service: a JobRequest (core's one job format), read strictly from untrusted
// JSON and checked against the service's limits.
#include <cstddef>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "study/job_request.h"

namespace facetlight::server {

// Configurable caps with defaults that protect a laptop.
struct ServiceLimits {
    uint64_t maxPhotons = 100'000'000;  // per job, trace and photon-map photons each
    int maxImageSide = 2048;
    size_t maxUploadBytes = 16 << 20;
    size_t maxQueued = 64;
    size_t maxBodyBytes = 1 << 20;
    size_t maxUrlBytes = 2048;
    uint64_t minFreeBytes = 256 << 20;  // new jobs and uploads get 507 when the data disk has less free
    size_t maxListBytes = 4 << 20;  // a page of GET /api/jobs stops at the job that passes this (issue 31)
    uint64_t maxMeshStoreBytes = uint64_t(1)
                                 << 30;  // uploaded meshes' files together; beyond, uploads get 507
    // A job estimated to take longer is refused (422); one that runs twice as long is stopped (job_budget.h).
    // 0: no limit.
    double maxJobSeconds = 600;
};

// Throws Error naming the field, also when it exceeds a limit of this service (with `limits`: new jobs;
// without: jobs already accepted). Missing `threads` means `defaultThreads`.
JobRequest parseJobSpec(const nlohmann::json& body, int defaultThreads,
                        const ServiceLimits* limits = nullptr);

// The job a client's form starts from (GET /api/defaults): every setting at the value a job that leaves it
// out gets here (threads: `defaultThreads`), and render, aset, tilt_series and fire_picture at their own; the
// canonical JSON without a mesh.
nlohmann::json jobDefaults(int defaultThreads);

// A job the store kept, read back when its record is loaded: the text is the canonical JSON written from its
// spec when it was accepted (toJson), so it holds every setting. Throws Error when it no longer reads.
JobRequest storedJobSpec(const nlohmann::json& request);

}  // namespace facetlight::server
