#pragma once
// The photon pass of a render: photons from the job's light traced through the stone by the statistics'
// own tracer (photon i is photon i of the trace), stored where they land on the floor (the caustic map's
// photons), and the directions of those leaving the crown binned for the angular plot.
#include <atomic>
#include <cstdint>
#include <vector>

#include "angular_plot.h"
#include "photon.h"
#include "photon_tracer.h"
#include "scene.h"

namespace facetlight {

struct FloorPhotons {
    std::vector<Photon> caustic;  // in photon-index order, whatever the thread count
    AngularHistogram crownExits;  // world directions of photons refracted out of table and crown
    uint64_t traced = 0;
    bool cancelled = false;
};

// Traces photons [0, count) of `trace`'s job with `threads` workers. Photons carry power
// scene.photonPower(count) and their wavelength when the scene is dispersive (else none: white light).
FloorPhotons traceFloorPhotons(const Scene& scene, const TraceScene& trace, uint64_t count, int threads,
                               std::atomic<uint64_t>* photonsDone = nullptr,
                               const std::atomic<bool>* cancel = nullptr);

}  // namespace facetlight
