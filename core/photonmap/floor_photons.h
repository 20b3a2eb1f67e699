#pragma once
// The photon pass of a render: photons from the job's light traced through the stone by the statistics'
// own tracer (photon i is photon i of the trace), stored where they land on the floor (the caustic map's
// photons), and the directions of those leaving the crown binned for the angular plot.
#include <cstdint>
#include <vector>

#include "photonmap/photon.h"
#include "stats/angular_histogram.h"
#include "trace/photon_tracer.h"
#include "util/distributed.h"
#include "util/run_control.h"

namespace facetlight {

struct FloorPhotons {
    std::vector<Photon> caustic;  // in photon-index order, whatever the thread count
    AngularHistogram crownExits;  // world directions of photons refracted out of table and crown
    uint64_t traced = 0;          // photons of the range traced (of the whole job after a distributed pass)
    bool cancelled = false;
};

// Traces photons [0, count) of the trace's job with `threads` workers, advancing control->done() by the
// photons traced. Photons carry power scene.photonPower(count) and their wavelength when the scene is
// dispersive (else none: white light).
FloorPhotons traceFloorPhotons(const TraceBase& trace, uint64_t count, int threads,
                               RunControl* control = nullptr);
// The same for blocks [firstBlock, lastBlock) of a job of `count` photons only (clipped to it): the caustic
// photons of consecutive block ranges, appended in range order, are those of the whole job.
FloorPhotons traceFloorPhotons(const TraceBase& trace, uint64_t count, uint64_t firstBlock,
                               uint64_t lastBlock, int threads, RunControl* control = nullptr);

// The photon pass spread over the ranks of `comm` (docs/distributed.md): each rank traces the blocks of
// partition(blockCount(count), rank, size), and every rank receives all caustic photons in photon-index
// order (the single-process map, bit for bit). The angular histogram is summed on rank 0 only; `cancelled`
// is true on every rank when any rank was cancelled. control->done() counts this rank's photons.
FloorPhotons traceFloorPhotons(Communicator& comm, const TraceBase& trace, uint64_t count, int threads,
                               RunControl* control = nullptr);

}  // namespace facetlight
