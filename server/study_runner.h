#pragma once
// How the queue's worker runs one job: a StudyRunner takes the job, the control it reports progress to and
// watches for a cancel, and for a sweep where its finished points are kept, and returns the results or throws
// (Canceled, Error). The queue only queues jobs and
// moves their states; where the work happens is the runner's business.
#include <memory>
#include <optional>

#include "job_spec.h"
#include "launcher.h"
#include "mesh_catalog.h"
#include "study/study.h"

namespace facetlight::server {

class StudyRunner {
  public:
    virtual ~StudyRunner() = default;
    virtual StudyResult run(const JobRequest& spec, RunControl& control,
                            const SweepCheckpoint& checkpoint) = 0;
};

// In the service's own process, on the worker's thread.
class InProcessRunner final : public StudyRunner {
  public:
    explicit InProcessRunner(const MeshCatalog& catalog) : catalog_(catalog) {}
    StudyResult run(const JobRequest& spec, RunControl& control, const SweepCheckpoint& checkpoint) override;

  private:
    const MeshCatalog& catalog_;
};

// Jobs the launch settings select run as child processes through the launcher (e.g. mpirun,
// docs/distributed.md); smaller ones in-process. A sweep's points are spread over the ranks; a sweep in a
// child starts afresh after a restart (its points are kept only in-process).
class LauncherRunner final : public StudyRunner {
  public:
    LauncherRunner(const MeshCatalog& catalog, LaunchSettings launch)
        : catalog_(catalog), launch_(std::move(launch)), inProcess_(catalog) {}
    StudyResult run(const JobRequest& spec, RunControl& control, const SweepCheckpoint& checkpoint) override;

  private:
    const MeshCatalog& catalog_;
    const LaunchSettings launch_;
    InProcessRunner inProcess_;
};

// The launcher runner with launch settings, else the in-process one.
std::unique_ptr<StudyRunner> makeStudyRunner(const MeshCatalog& catalog,
                                             const std::optional<LaunchSettings>& launch);

}  // namespace facetlight::server
