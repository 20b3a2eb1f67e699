#include "study/study.h"

#include <chrono>
#include <sstream>
#include <thread>

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

// Copies a running phase's progress counter into the study's, and the study's cancel flag into the phase's,
// every few milliseconds until destroyed.
class ProgressMirror {
  public:
    ProgressMirror(StudyControl& control, std::atomic<uint64_t>& done, std::atomic<bool>& cancel)
        : thread_([&control, &done, &cancel, this] {
              while (!stop_.load()) {
                  control.done.store(done.load(std::memory_order_relaxed), std::memory_order_relaxed);
                  if (control.cancel.load()) cancel.store(true);
                  std::this_thread::sleep_for(std::chrono::milliseconds(5));
              }
              control.done.store(done.load());
          }) {}
    ~ProgressMirror() {
        stop_ = true;
        thread_.join();
    }

  private:
    std::atomic<bool> stop_{false};
    std::thread thread_;
};

void enterPhase(StudyControl& control, StudyPhase phase, uint64_t total) {
    if (control.cancel.load()) throw Canceled();
    control.done = 0;
    control.total = total;
    control.phase = phase;
}

}  // namespace

std::string_view studyPhaseName(StudyPhase phase) {
    switch (phase) {
        case StudyPhase::Queued:
            return "queued";
        case StudyPhase::Tracing:
            return "tracing";
        case StudyPhase::PhotonMap:
            return "photon_map";
        case StudyPhase::Rendering:
            return "rendering";
        case StudyPhase::Done:
            return "done";
    }
    return "queued";
}

StudyResult runStudy(const Stone& stone, const StudySettings& settings, StudyControl& control) {
    SerialCommunicator serial;
    return runStudy(stone, settings, control, serial);
}

StudyResult runStudy(const Stone& stone, const StudySettings& settings, StudyControl& control,
                     Communicator& comm) {
    StudyResult result;
    const int threads = settings.trace.threads;

    enterPhase(control, StudyPhase::Tracing, localPhotons(comm, settings.trace.photons));
    TraceResult traced;
    {
        TraceControl traceControl;
        ProgressMirror mirror(control, traceControl.photonsDone, traceControl.cancel);
        traced = traceDistributed(comm, stone, settings.trace, &traceControl);
    }
    // Every rank takes the same way out, so none is left waiting in a collective.
    if (anyRank(comm, traced.cancelled || control.cancel.load())) throw Canceled();
    if (comm.isRoot()) {
        result.stats = statsToJson(traced.stats, stone, settings.trace, traced.timing);
        std::ostringstream csv;
        writeFacetCsv(csv, traced.stats, stone);
        result.statsCsv = csv.str();
        result.heatmapPng = encodePng(facetHeatmap(stone, traced.stats));
        result.heatmapLayout = toJson(heatmapLayout(stone), stone).dump();
    }

    if (!settings.render) {
        enterPhase(control, StudyPhase::Done, 0);
        return result;
    }
    const RenderSettings& r = *settings.render;
    const Scene scene(stone, settings.trace);
    const TraceScene traceScene(stone, settings.trace);

    // Every rank traces its share of the map photons and builds the whole map (docs/distributed.md).
    enterPhase(control, StudyPhase::PhotonMap, localPhotons(comm, r.mapPhotons));
    FloorPhotons photons;
    {
        std::atomic<uint64_t> done{0};
        std::atomic<bool> cancel{false};
        ProgressMirror mirror(control, done, cancel);
        photons = traceFloorPhotons(comm, scene, traceScene, r.mapPhotons, threads, &done, &cancel);
    }
    if (photons.cancelled || control.cancel.load()) throw Canceled();
    const PhotonMap caustics(std::move(photons.caustic), threads);
    if (comm.isRoot()) {
        result.angularPng = encodePng(angularPlot(
            photons.crownExits, std::to_string(photons.crownExits.total) + " of " +
                                    std::to_string(r.mapPhotons) + " photons (" +
                                    std::string(kLightModelNames.name(settings.trace.light.model)) +
                                    " light), refracted out of table and crown"));
    }

    enterPhase(control, StudyPhase::Rendering,
               sharePixelCount(r.width, r.height, {comm.rank(), comm.size()}));
    RenderedImage image;
    {
        std::atomic<uint64_t> done{0};
        std::atomic<bool> cancel{false};
        ProgressMirror mirror(control, done, cancel);
        image = render(comm, scene, caustics, r, threads, settings.trace.seed, {&done, &cancel});
    }
    if (image.cancelled || control.cancel.load()) throw Canceled();
    if (!comm.isRoot()) return result;
    result.renderPng = encodePng(toDisplay(image));
    enterPhase(control, StudyPhase::Done, 0);
    return result;
}

}  // namespace facetlight
