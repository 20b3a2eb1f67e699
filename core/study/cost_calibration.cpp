#include "study/cost_calibration.h"

#include <chrono>
#include <vector>

#include "cuts/cut_library.h"
#include "photonmap/floor_photons.h"
#include "photonmap/photon_map.h"
#include "pictures/aset_picture.h"
#include "pictures/webp_animation.h"
#include "render/aset.h"
#include "render/fire_picture.h"
#include "render/renderer.h"
#include "scene/scene.h"
#include "study/study.h"
#include "trace/photon_tracer.h"
#include "trace/trace_base.h"
#include "viewer/viewer_figures.h"

namespace facetlight {
namespace {

// Wall-clock seconds of `work`, at least a microsecond so that no rate is zero.
template <class Work>
double seconds(Work&& work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
    return std::max(took.count(), 1e-6);
}

}  // namespace

// Why these rates are honest: each is the time of the very function a job's phase calls (runStudy's), in this
// build (its SIMD target, any sanitizer) on this machine, on the stone the verdict compares every job with.
// The work is fixed (stone, settings, seeds), so only the clock varies between starts. The units a job counts
// (photons, pixels x samples x bounces, view rays) are traced independently of each other, so time grows in
// proportion to them; the small runs here also carry the fixed costs (building the scene, starting a phase),
// which makes their rates a little high, on the safe side, as does a machine busy with other work. What they
// cannot see (threads that do not scale, slower stones) is kCostSafetyFactor's business.
CostRates calibrateCostRates() {
    const Stone stone = Stone::build(makeCut("round_brilliant"), "calibration");
    TraceSettings t;
    t.threads = 1;
    t.seed = 1;
    CostRates rates;

    // First, so that what a process does once (tables, the SIMD dispatch) is not counted in a rate below.
    StudySettings small;
    small.trace = t;
    small.trace.photons = 1000;
    small.trace.viewer.enabled = false;
    small.render = RenderSettings{};
    small.render->width = small.render->height = 16;
    small.render->samples = 1;
    small.render->mapPhotons = 1000;
    RunControl control;
    rates.jobFiles = seconds([&] { runStudy(stone, small, control); });

    t.photons = 50'000;
    const Scene scene(stone, t);
    const TraceBase base(scene, t);
    rates.tracePhoton = seconds([&] { trace(base); }) / double(t.photons);

    TraceSettings fire = t;
    fire.fire.enabled = true;
    fire.photons = 25'000;
    const TraceBase fireBase(scene, fire);
    rates.fireTracePhoton = seconds([&] { trace(fireBase); }) / double(fire.photons);

    TraceSettings viewer = t;
    viewer.viewer.office.points = 200;
    viewer.viewer.spot.photons = 10'000;
    rates.viewerUnit = seconds([&] { viewStone(stone, viewer); }) / double(viewerUnits(viewer.viewer));

    const uint64_t mapPhotons = kCalibrationMapPhotons;
    PhotonMap caustics;
    rates.mapPhoton =
        seconds([&] { caustics = PhotonMap(traceFloorPhotons(base, mapPhotons, 1).caustic, 1); }) /
        double(mapPhotons);

    RenderSettings r;
    r.width = r.height = 32;
    r.samples = 2;
    const double rays = double(r.width) * r.height * r.maxDepth;
    rates.renderRay = seconds([&] { render(scene, caustics, r, 1, t.seed); }) / (rays * r.samples);

    FirePictureSettings firePicture;
    firePicture.wavelengths = 4;
    rates.fireRay = seconds([&] { facetlight::firePicture(scene, r, firePicture, 1, t.seed); }) /
                    (rays * firePicture.wavelengths);

    AsetSettings aset;
    aset.samples = 2;
    AsetView view;
    rates.asetRay = seconds([&] { view = asetView(base, r.camera, r.width, r.height, aset, 1, t.seed); }) /
                    (double(r.width) * r.height * aset.samples);
    const int frames = 3;
    rates.framePixel = seconds([&] {
                           std::vector<Image> pictures;
                           for (int k = 0; k < frames; ++k)
                               pictures.push_back(asetPicture(view, aset, "calibration"));
                           encodeAnimatedWebp(pictures, 120);
                       }) /
                       (double(frames) * r.width * r.height);
    return rates;
}

}  // namespace facetlight
