#include "viewer/spot_fire.h"

#include <array>
#include <cmath>

#include "optics/observer.h"
#include "trace/fire_trace.h"
#include "trace/photon_walker.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/random.h"

namespace facetlight {
namespace {

// Keeps the spot set-up's random streams apart from the tracer's and the office's.
constexpr uint64_t kSpotStreams = 0x53504f54ULL;
constexpr uint64_t kPhotonsPerBlock = 4096;

using BandExit = PhotonWalker::BandExit;

// The bounding sphere of the stone's vertices about its bounds' centre.
double sphereRadius(const Stone& stone, const Vec3& centre) {
    double r2 = 0;
    for (const Vec3& v : stone.vertices) r2 = std::max(r2, dot(v - centre, v - centre));
    return std::sqrt(r2);
}

}  // namespace

void SpotTally::merge(const SpotTally& o) {
    photons += o.photons;
    hit += o.hit;
    seen += o.seen;
    pairs += o.pairs;
    coloured += o.coloured;
    split += o.split;
}

std::vector<Vec3> spotLamps(const ViewerSettings& settings) {
    // Only the directions matter here: any scale.
    const Observer observer(settings, 1.0);
    const SpotSettings& s = settings.spot;
    const double e = radians(s.elevationDeg);
    std::vector<Vec3> lamps;
    for (int k = 0; k < s.lamps; ++k) {
        const double phi = 2 * M_PI * (k + 0.5) / s.lamps;
        const Vec3 toLamp(std::cos(e) * std::cos(phi), std::cos(e) * std::sin(phi), std::sin(e));
        double radiance;
        if (observer.office(toLamp, radiance) == Seen::Viewer) continue;  // behind the viewer's head or body
        lamps.push_back(-toLamp);
    }
    if (lamps.empty())
        throw Error("viewer.spot.lamps",
                    "the viewer's head and shoulders hide every lamp: raise the lamps or move them");
    return lamps;
}

SpotTally spotFire(const TraceBase& trace, const ViewerSettings& settings, RunControl* control,
                   bool& finished) {
    const Scene& scene = trace.scene();
    const Stone& stone = scene.stone();
    const Observer observer(settings, 1.0);
    const std::vector<Vec3> lamps = spotLamps(settings);
    std::vector<StonePose> poses;
    for (int a = 0; a < settings.azimuths; ++a)
        for (int k = 0; k < settings.tilts; ++k) poses.emplace_back(settings.tiltDeg(k), settings.turnDeg(a));
    const Vec3 centre = stone.bounds.center();
    const double radius = sphereRadius(stone, centre) * 1.001;
    const std::array<FireBand, kFireBands> bands = fireBands(scene);
    const double cosPupil = std::cos(std::atan(settings.pupilMm / 2 / settings.distanceMm) * 2);
    const uint64_t streams = mix64(trace.settings().seed ^ kSpotStreams);

    const WorkerStates<SpotTally> workers = parallelForBlocks(
        BlockLoop{0, settings.spot.photons, kPhotonsPerBlock, trace.settings().threads}, control, SpotTally{},
        [&](SpotTally& t, uint64_t first, uint64_t last) {
            for (uint64_t i = first; i < last; ++i) {
                ++t.photons;
                const StonePose& pose = poses[i % poses.size()];
                const Vec3 dir = pose.toStone(lamps[(i / poses.size()) % lamps.size()]);
                Rng rng(streams, i);
                // A uniform point of the disc across the beam that covers the stone.
                const double r = radius * std::sqrt(rng.uniformDouble()),
                             phi = 2 * M_PI * rng.uniformDouble();
                const Vec3 u =
                    normalize(std::abs(dir.z) < 0.9 ? cross(dir, Vec3(0, 0, 1)) : cross(dir, Vec3(1, 0, 0)));
                const Vec3 v = cross(dir, u);
                const LightRay ray{
                    centre - dir * (2 * radius) + u * (r * std::cos(phi)) + v * (r * std::sin(phi)), dir};
                std::array<BandExit, kFireBands> exit;
                for (int b = 0; b < kFireBands; ++b) {
                    PhotonWalker::Photon ph;
                    ph.rng = rng;
                    PhotonWalker::setBand(trace, bands[b], ph);
                    if (PhotonWalker::enter(trace, scene, ray, exit[b], ph))
                        while (PhotonWalker::step(trace, scene, exit[b], ph)) {
                        }
                }
                if (exit[0].outcome == PhotonOutcome::Missed) continue;
                ++t.hit;
                // Out through table or crown toward the viewer, in the world.
                const auto toViewer = [&](const BandExit& b, Vec3& world) {
                    if (b.outcome != PhotonOutcome::Exited || !trace.crownSide(b.facet)) return false;
                    world = pose.toWorld(Vec3{b.dir.x, b.dir.y, b.dir.z});
                    return observer.inViewingCone(world);
                };
                Vec3 red, mid, blue;
                t.seen += toViewer(exit[1], mid);
                const bool r0 = toViewer(exit[kFireRed], red), b0 = toViewer(exit[kFireBlue], blue);
                if (!r0 && !b0) continue;
                if (!(r0 && b0 && exit[kFireRed].path == exit[kFireBlue].path)) {
                    ++t.split;
                    continue;
                }
                ++t.pairs;
                t.coloured += dot(red, blue) < cosPupil;
            }
            return last - first;
        });
    SpotTally tally;
    for (const SpotTally& t : workers.states) tally.merge(t);
    finished = workers.finished;
    return tally;
}

}  // namespace facetlight
