// A build without MPI: every run is one process.
#include "process_communicator.h"

namespace facetlight::cli {

Communicator& processCommunicator() {
    static SerialCommunicator serial;
    return serial;
}

void abortOtherRanks(int) {}

}  // namespace facetlight::cli
