#include "study_runner.h"

namespace facetlight::server {

StudyResult InProcessRunner::run(const JobRequest& spec, RunControl& control,
                                 const SweepCheckpoint& checkpoint) {
    if (spec.settings.sweep) {
        SerialCommunicator serial;
        return runSweepJob(catalog_.shapeSource(spec.mesh), spec.settings, control, serial, checkpoint);
    }
    if (!spec.cut.empty()) return runStudy(cutStone(spec, catalog_.shapeSource(spec.mesh)), spec.settings, control);
    const std::shared_ptr<const Stone> stone = catalog_.resolve(spec.mesh);
    if (spec.name.empty() || spec.name == stone->name) return runStudy(*stone, spec.settings, control);
    Stone named = *stone;  // a copy to rename: the catalog's stone is shared
    named.name = spec.name;
    return runStudy(named, spec.settings, control);
}

StudyResult LauncherRunner::run(const JobRequest& spec, RunControl& control,
                                const SweepCheckpoint& checkpoint) {
    if (!useLauncher(launch_, spec.settings)) return inProcess_.run(spec, control, checkpoint);
    // A sweep's designs, and a cut (of a library shape or a GemCad design's tiers), are built by the child, from
    // a file it can read.
    if (spec.settings.sweep || !spec.cut.empty()) {
        JobRequest located = spec;
        located.mesh = catalog_.shapeSource(spec.mesh);
        return runStudyInChild(launch_, located, control);
    }
    catalog_.resolve(spec.mesh);  // a mesh that does not build fails here, as it would in-process
    const ChildMesh child = catalog_.locate(spec.mesh);
    JobRequest located = spec;  // the same job, its mesh named as the child reads it
    located.mesh = child.source;
    if (located.name.empty()) located.name = child.name;
    return runStudyInChild(launch_, located, control);
}

std::unique_ptr<StudyRunner> makeStudyRunner(const MeshCatalog& catalog,
                                             const std::optional<LaunchSettings>& launch) {
    if (launch) return std::make_unique<LauncherRunner>(catalog, *launch);
    return std::make_unique<InProcessRunner>(catalog);
}

}  // namespace facetlight::server
