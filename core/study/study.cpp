#include "study/study.h"

#include <cstdio>
#include <sstream>
#include <vector>

#include "photonmap/floor_photons.h"
#include "photonmap/photon_map.h"
#include "pictures/angular_plot.h"
#include "pictures/aset_picture.h"
#include "pictures/colour_picture.h"
#include "pictures/design_diagram.h"
#include "pictures/doubling_picture.h"
#include "pictures/heatmap.h"
#include "pictures/polariscope_chart.h"
#include "pictures/tilt_chart.h"
#include "pictures/webp_animation.h"
#include "render/aset.h"
#include "render/fire_picture.h"
#include "render/renderer.h"
#include "render/tilt_series.h"
#include "scene/scene.h"
#include "stone/stone_json.h"
#include "trace/distributed_trace.h"
#include "trace/photon_tracer.h"
#include "util/error.h"
#include "viewer/verdict.h"

namespace facetlight {
namespace {

constexpr int kTiltFrameMs = 120;  // 21 frames: a 2.5 s sweep

void enterPhase(RunControl& control, RunPhase phase, uint64_t total) {
    if (control.cancelled()) throw Canceled();
    control.startPhase(phase, total);
}

// The pictures of the render's size a study draws after its render: the fire picture, the face-up ASET view
// and the tilt series' frames.
int viewCount(const StudySettings& settings) {
    return (settings.firePicture ? 1 : 0) + (settings.aset ? 1 : 0) +
           (settings.tiltSeries ? settings.tiltSeries->frames() : 0);
}

}  // namespace

uint64_t studyUnits(const StudySettings& settings, RunPhase phase) {
    switch (phase) {
        case RunPhase::Tracing:
            return settings.trace.photons;
        case RunPhase::Viewing:
            // The stone's view rays and lamp photons, and as many again for the reference it is judged
            // against; the polariscope's photons; the doubling's and the colour view's pixels.
            return (settings.trace.viewer.enabled ? 2 * viewerUnits(settings.trace.viewer) : 0) +
                   (settings.polariscope
                        ? uint64_t(settings.polariscope->angles) * settings.polariscope->photons
                        : 0) +
                   (settings.doubling
                        ? uint64_t(settings.doubling->pictureSize) * settings.doubling->pictureSize
                        : 0) +
                   (settings.colour ? uint64_t(settings.colour->pictureSize) * settings.colour->pictureSize
                                    : 0);
        case RunPhase::PhotonMap:
            return settings.render ? settings.render->mapPhotons : 0;
        case RunPhase::Rendering:
            // The render's pixels, and as many again for the fire picture, the ASET view and each tilt frame.
            return settings.render ? uint64_t(settings.render->width) * uint64_t(settings.render->height) *
                                         uint64_t(1 + viewCount(settings))
                                   : 0;
        case RunPhase::Queued:
        case RunPhase::Done:
            break;
    }
    return 0;
}

StudyResult runSweepJob(const std::string& shape, const StudySettings& settings, RunControl& control,
                        Communicator& comm, const SweepCheckpoint& checkpoint) {
    if (!settings.sweep) throw Error("sweep", "the job is not a sweep");
    const SweepRequest& request = *settings.sweep;
    const SweepOutputs out = runSweepRequest(planSweepOf(shape, request, settings.trace, settings.colour),
                                             request, control, comm, checkpoint);
    StudyResult result;
    if (!comm.isRoot()) return result;
    result.file("sweep.json") = out.json();
    result.file("sweep.csv") = out.csv();
    result.file("sweep.png") = out.pictures.front().second;
    if (!out.best.is_null()) {
        result.file("best.json") = out.best.dump(2) + "\n";
        result.file("best.obj") = out.bestObj;
        result.file("best.asc") = out.bestAsc;
    }
    return result;
}

StudyResult runStudy(const Stone& stone, const StudySettings& settings, RunControl& control) {
    SerialCommunicator serial;
    return runStudy(stone, settings, control, serial);
}

StudyResult runStudy(const Stone& stone, const StudySettings& settings, RunControl& control,
                     Communicator& comm) {
    const Scene scene(stone, settings.trace);
    const TraceBase trace(scene, settings.trace);
    if (settings.aset) {
        if (!settings.render)
            throw Error("aset must come with a render: it is seen through the render's camera");
        settings.aset->validate();
    }
    if (settings.firePicture && !settings.render)
        throw Error("fire_picture must come with a render: it is seen through the render's camera");
    if (settings.tiltSeries) {
        if (!settings.render)
            throw Error("tilt_series must come with a render: it is seen through the render's camera");
        settings.tiltSeries->validate();
    }
    StudyResult result;
    const int threads = settings.trace.threads;

    enterPhase(control, RunPhase::Tracing, localPhotons(comm, settings.trace.photons));
    const TraceResult traced = traceDistributed(comm, trace, &control);
    // Every rank takes the same way out, so none is left waiting in a collective.
    if (anyRank(comm, traced.cancelled || control.cancelled())) throw Canceled();
    if (comm.isRoot()) {
        result.stats = traceReport(traced, stone, settings.trace);
        const DesignFacts facts = designFacts(stone, settings.trace);
        addDesignFacts(result.stats, facts);
        std::ostringstream csv;
        writeFacetCsv(csv, traced.stats, stone);
        result.file("stats.csv") = csv.str();
        result.file("heatmap.png") = encodePng(facetHeatmap(stone, traced.stats));
        result.file("heatmap.json") = toJson(heatmapLayout(stone), stone).dump();
        // At the trace's scale, as the trace's mm (absorption, the viewer's distances) are.
        result.file("stone.json") = stoneGeometryJson(stone, settings.trace.sizeMm / scene.diameter()).dump();
        if (facts.size) result.file("diagram.png") = encodePng(designDiagram(stone, facts.sheet, *facts.size));
        if (traced.fire) {
            result.file("heatmap_fire.png") = encodePng(fireHeatmap(stone, *traced.fire));
        }
    }
    if (settings.trace.viewer.enabled || settings.polariscope || settings.doubling || settings.colour) {
        // Rank 0 alone: the viewer's rays, the polariscope's photons and the doubling's and colour view's
        // rays are a small fraction of a trace's.
        enterPhase(control, RunPhase::Viewing, comm.isRoot() ? studyUnits(settings, RunPhase::Viewing) : 0);
        if (comm.isRoot() && settings.trace.viewer.enabled)
            result.stats["viewer"] = viewerReport(stone, settings.trace, &control);
        if (comm.isRoot() && settings.polariscope && !control.cancelled()) {
            const Polariscope p = polariscope(stone, settings.trace, *settings.polariscope, &control);
            result.stats["polariscope"] = toJson(p);
            result.file("polariscope.png") =
                encodePng(polariscopeChart(p, "Polariscope: " + stone.name + ", " +
                                                  chooseMaterial(settings.trace, stone).material.name()));
            if (settings.polariscope->pictureSize > 0)
                result.file("polariscope.webp") = encodeAnimatedWebp(polariscopeFrames(p), kPolariscopeFrameMs);
        }
        if (comm.isRoot() && settings.doubling && !control.cancelled()) {
            const Doubling d = doubling(stone, settings.trace, *settings.doubling, &control);
            result.stats["doubling"] = toJson(d);
            result.file("doubling.png") = encodePng(doublingPicture(d, doublingTitle(stone, settings.trace)));
        }
        if (comm.isRoot() && settings.colour && !control.cancelled()) {
            const ColourView v = colourView(stone, settings.trace, *settings.colour, &control);
            if (v.cancelled) throw Canceled();
            result.stats["colour"] = toJson(v);
            result.file("colour.png") = encodePng(colourPicture(v, colourTitle(stone, settings.trace)));
        }
        if (anyRank(comm, control.cancelled())) throw Canceled();
    }

    if (!settings.render) {
        enterPhase(control, RunPhase::Done, 0);
        return result;
    }
    const RenderSettings& r = *settings.render;

    // Every rank traces its share of the map photons and builds the whole map (docs/distributed.md).
    enterPhase(control, RunPhase::PhotonMap, localPhotons(comm, r.mapPhotons));
    FloorPhotons photons = traceFloorPhotons(comm, trace, r.mapPhotons, threads, &control);
    if (photons.cancelled || control.cancelled()) throw Canceled();
    const PhotonMap caustics(std::move(photons.caustic), threads);
    if (comm.isRoot()) {
        result.file("angular.png") = encodePng(angularPlot(
            photons.crownExits, std::to_string(photons.crownExits.total) + " of " +
                                    std::to_string(r.mapPhotons) + " photons (" +
                                    std::string(kLightModelNames.name(settings.trace.light.model)) +
                                    " light), refracted out of table and crown"));
    }

    const uint64_t asetPixels =
        comm.isRoot() ? uint64_t(r.width) * uint64_t(r.height) * viewCount(settings) : 0;
    enterPhase(control, RunPhase::Rendering,
               sharePixelCount(r.width, r.height, {comm.rank(), comm.size()}) + asetPixels);
    const RenderedImage image = render(comm, scene, caustics, r, threads, settings.trace.seed, &control);
    if (image.cancelled || control.cancelled()) throw Canceled();
    if (!comm.isRoot()) return result;
    result.file("render.png") = encodePng(toDisplay(image));
    if (settings.firePicture) {
        // Rank 0 alone, like the views below.
        const FirePicture fire =
            firePicture(scene, r, *settings.firePicture, threads, settings.trace.seed, &control);
        if (fire.cancelled || control.cancelled()) throw Canceled();
        result.file("fire.png") = encodePng(toDisplay(fire));
    }
    if (settings.aset) {
        // Rank 0 alone: a few view rays per pixel, far cheaper than the render.
        const AsetView view = asetView(trace, r.camera, r.width, r.height, *settings.aset, threads,
                                       settings.trace.seed, &control);
        if (view.cancelled || control.cancelled()) throw Canceled();
        result.stats["aset"] = toJson(view, *settings.aset);
        result.file("aset.png") = encodePng(asetPicture(view, *settings.aset, "ASET view of " + stone.name));
    }
    if (settings.tiltSeries) {
        const AsetSettings aset = settings.aset.value_or(AsetSettings{});
        const TiltSeries series =
            tiltSeries(trace, r.camera, r.width, r.height, aset, *settings.tiltSeries, &control);
        if (series.cancelled || control.cancelled()) throw Canceled();
        result.stats["tilt_series"] = toJson(series, *settings.tiltSeries);
        std::vector<Image> frames;
        const std::string axis = tiltAxisName(settings.tiltSeries->axisDeg);
        for (const TiltFrame& f : series.frames) {
            char tilt[32];
            std::snprintf(tilt, sizeof tilt, " tilted %+.1f deg about ", f.tiltDeg);
            frames.push_back(asetPicture(f.view, aset, stone.name + tilt + axis));
        }
        result.file("tilt.webp") = encodeAnimatedWebp(frames, kTiltFrameMs);
        result.file("tilt.png") = encodePng(tiltChart(series, "Light return against tilt: " + stone.name));
    }
    enterPhase(control, RunPhase::Done, 0);
    return result;
}

}  // namespace facetlight
