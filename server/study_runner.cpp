#include "study_runner.h"

namespace facetlight::server {

StudyResult InProcessRunner::run(const JobSpec& spec, RunControl& control) {
    return runStudy(*catalog_.resolve(spec.mesh), spec.settings, control);
}

StudyResult LauncherRunner::run(const JobSpec& spec, RunControl& control) {
    if (!useLauncher(launch_, spec.settings)) return inProcess_.run(spec, control);
    catalog_.resolve(spec.mesh);  // a mesh that does not build fails here, as it would in-process
    return runStudyInChild(launch_, catalog_.locate(spec.mesh), spec.settings, control);
}

std::unique_ptr<StudyRunner> makeStudyRunner(const MeshCatalog& catalog,
                                             const std::optional<LaunchSettings>& launch) {
    if (launch) return std::make_unique<LauncherRunner>(catalog, *launch);
    return std::make_unique<InProcessRunner>(catalog);
}

}  // namespace facetlight::server
