#pragma once
// Running a study as a child process, through a launcher such as `mpirun -np 4 --hostfile hosts`, instead of
// in the service's own process (docs/distributed.md). The child is `facetlight study --job FILE --out DIR
// --progress-json`: its rank 0 writes progress as JSON lines on stderr and the results into DIR, which must
// be a directory every node shares. The child runs in a process group of its own, so cancelling ends the
// launcher and the ranks it started.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "child_process.h"
#include "study/job_request.h"

namespace facetlight::server {

struct LaunchSettings {
    std::vector<std::string> launcher;  // words before the facetlight command; empty: run it directly
    std::string executable;             // the facetlight tool on every node; empty: next to this program
    std::filesystem::path workDir;      // where job folders are made; empty: the system's temp directory
    uint64_t minPhotons = 0;            // jobs with fewer trace + photon-map photons run in-process
    std::chrono::milliseconds cancelGrace{5000};  // between SIGTERM and SIGKILL
};

// Shell-like words: blanks separate, single and double quotes group, backslash escapes. Throws Error on an
// unclosed quote.
std::vector<std::string> splitWords(std::string_view text);

// Whether a job of these settings goes to the launcher rather than in-process.
bool useLauncher(const LaunchSettings& launch, const StudySettings& settings);

// The stone for the child: a file path or shipped shape name that resolveStone() reads on every node, and
// the name the results show (empty: the one the file gives).
struct ChildMesh {
    std::string source;
    std::string name;
};

// Runs the job in a child and returns its results. `spec` names its mesh as the child reads it (a ChildMesh's
// source, or a shape of the cut library). Follows the child's progress into `control`; when control.cancel()
// is called, ends the child's process group (SIGTERM, then SIGKILL after the grace period) and throws
// Canceled. A launch that fails or exits non-zero throws Error with the end of the child's output.
StudyResult runStudyInChild(const LaunchSettings& launch, const JobRequest& spec, RunControl& control);

// Reads a progress line {"phase": "tracing", "done": 1, "total": 2} into control; false if it is not one.
bool applyProgressLine(std::string_view line, RunControl& control);

}  // namespace facetlight::server
