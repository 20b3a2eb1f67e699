#pragma once
// The communicator of this facetlight process: MPI's world when launched under mpirun in a build with
// FACETLIGHT_MPI (cli/mpi_communicator.cpp), else serial (cli/serial_communicator.cpp). A plain run never
// touches the MPI runtime.
#include "util/distributed.h"

namespace facetlight::cli {

// Starts MPI on first use when the environment says we run under a launcher.
Communicator& processCommunicator();
// Ends the run after a fatal error: with other ranks, takes them down too rather than leaving them blocked
// in a collective. Returns only in a single-process run.
void abortOtherRanks(int exitCode);

}  // namespace facetlight::cli
