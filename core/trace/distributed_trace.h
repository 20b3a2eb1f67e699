#pragma once
// A trace spread over the ranks of a Communicator: each rank traces a contiguous range of the job's photon
// blocks with its own threads, and the integer tallies are summed on rank 0. Photon i's randomness depends on
// (seed, i) only, so rank 0's statistics equal a single-process trace() bit for bit, for any rank count.
#include "trace/photon_tracer.h"
#include "util/distributed.h"

namespace facetlight {

// Rank 0 gets the whole job's statistics; other ranks keep their own share. `cancelled` is true on rank 0
// when any rank was cancelled. control->done() counts this rank's photons only.
TraceResult traceDistributed(Communicator& comm, const TraceBase& trace, RunControl* control = nullptr);

// The photons this rank traces (the blocks of partition(blockCount(photons), rank, size)).
uint64_t localPhotons(const Communicator& comm, uint64_t photons);

}  // namespace facetlight
