#include "study/study.h"

#include <sstream>

#include "intersect/scene.h"
#include "photonmap/floor_photons.h"
#include "photonmap/photon_map.h"
#include "pictures/angular_plot.h"
#include "pictures/heatmap.h"
#include "render/renderer.h"
#include "trace/distributed_trace.h"
#include "trace/photon_tracer.h"
#include "util/error.h"

namespace facetlight {
namespace {

void enterPhase(RunControl& control, RunPhase phase, uint64_t total) {
    if (control.cancelled()) throw Canceled();
    control.startPhase(phase, total);
}

}  // namespace

uint64_t studyUnits(const StudySettings& settings, RunPhase phase) {
    switch (phase) {
        case RunPhase::Tracing:
            return settings.trace.photons;
        case RunPhase::PhotonMap:
            return settings.render ? settings.render->mapPhotons : 0;
        case RunPhase::Rendering:
            return settings.render ? uint64_t(settings.render->width) * uint64_t(settings.render->height) : 0;
        case RunPhase::Queued:
        case RunPhase::Done:
            break;
    }
    return 0;
}

StudyResult runStudy(const Stone& stone, const StudySettings& settings, RunControl& control) {
    SerialCommunicator serial;
    return runStudy(stone, settings, control, serial);
}

StudyResult runStudy(const Stone& stone, const StudySettings& settings, RunControl& control,
                     Communicator& comm) {
    const Scene scene(stone, settings.trace);
    StudyResult result;
    const int threads = settings.trace.threads;

    enterPhase(control, RunPhase::Tracing, localPhotons(comm, settings.trace.photons));
    const TraceResult traced = traceDistributed(comm, scene, &control);
    // Every rank takes the same way out, so none is left waiting in a collective.
    if (anyRank(comm, traced.cancelled || control.cancelled())) throw Canceled();
    if (comm.isRoot()) {
        result.stats = statsToJson(traced.stats, stone, settings.trace, traced.timing);
        std::ostringstream csv;
        writeFacetCsv(csv, traced.stats, stone);
        result.statsCsv = csv.str();
        result.heatmapPng = encodePng(facetHeatmap(stone, traced.stats));
        result.heatmapLayout = toJson(heatmapLayout(stone), stone).dump();
    }

    if (!settings.render) {
        enterPhase(control, RunPhase::Done, 0);
        return result;
    }
    const RenderSettings& r = *settings.render;

    // Every rank traces its share of the map photons and builds the whole map (docs/distributed.md).
    enterPhase(control, RunPhase::PhotonMap, localPhotons(comm, r.mapPhotons));
    FloorPhotons photons = traceFloorPhotons(comm, scene, r.mapPhotons, threads, &control);
    if (photons.cancelled || control.cancelled()) throw Canceled();
    const PhotonMap caustics(std::move(photons.caustic), threads);
    if (comm.isRoot()) {
        result.angularPng = encodePng(angularPlot(
            photons.crownExits, std::to_string(photons.crownExits.total) + " of " +
                                    std::to_string(r.mapPhotons) + " photons (" +
                                    std::string(kLightModelNames.name(settings.trace.light.model)) +
                                    " light), refracted out of table and crown"));
    }

    enterPhase(control, RunPhase::Rendering, sharePixelCount(r.width, r.height, {comm.rank(), comm.size()}));
    const RenderedImage image = render(comm, scene, caustics, r, threads, settings.trace.seed, &control);
    if (image.cancelled || control.cancelled()) throw Canceled();
    if (!comm.isRoot()) return result;
    result.renderPng = encodePng(toDisplay(image));
    enterPhase(control, RunPhase::Done, 0);
    return result;
}

}  // namespace facetlight
