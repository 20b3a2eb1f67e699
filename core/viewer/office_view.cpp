#include "viewer/office_view.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "optics/observer.h"
#include "trace/photon_walker.h"
#include "util/parallel.h"
#include "util/random.h"

namespace facetlight {
namespace {

// Keeps the office's random streams apart from the tracer's, the renderer's and the ASET view's.
constexpr uint64_t kOfficeStreams = 0x4f4646494345ULL;
constexpr uint64_t kPointsPerBlock = 64;

uint64_t fixedPoint(double x) {
    return uint64_t(x * kViewerScale + 0.5);
}

// What one view ray met, in the world.
struct ViewRay {
    const Stone& stone;
    const Observer& observer;
    const StonePose& pose;
    Seen seen = Seen::Trapped;
    double radiance = 0;
    bool table = false;   // went in through the table
    bool girdle = false;  // met the girdle inside
    bool head = false;    // met the viewer's head

    void see(const Vec3f& dir) {
        const Vec3 world = pose.toWorld(Vec3{dir.x, dir.y, dir.z});
        seen = observer.office(world, radiance);
        head = seen == Seen::Viewer && observer.head(world);
    }
    void reflectedAtEntry(uint32_t, const Vec3f&, const Vec3f& dir) { see(dir); }
    void entered(uint32_t f) { table = stone.facets[f].region == Region::Table; }
    void internalReflection(uint32_t f) { girdle |= stone.facets[f].region == Region::Girdle; }
    void exited(uint32_t f, const Vec3f&, const Vec3f& dir, uint32_t) {
        girdle |= stone.facets[f].region == Region::Girdle;
        see(dir);
    }
    void trapped(uint32_t) { seen = Seen::Trapped; }
    void lost(uint32_t) { seen = Seen::Trapped; }
    void absorbed(uint32_t) { seen = Seen::Trapped; }  // dark, as trapped light
};

// The largest distance of a vertex from the stone's axis: the disc the face-up points are drawn on.
double axisRadius(const Stone& stone) {
    double r2 = 0;
    for (const Vec3& v : stone.vertices) r2 = std::max(r2, v.x * v.x + v.y * v.y);
    return std::sqrt(r2);
}

// Half the radius of the circle of the table's area: the table's centre, where a nail-head shows; 0 without a
// table.
double tableCentreRadius(const Stone& stone) {
    for (const Facet& f : stone.facets)
        if (f.region == Region::Table) return std::sqrt(f.area / M_PI) / 2;
    return 0;
}

}  // namespace

void PointMean::add(double pointMean) {
    const uint64_t m = fixedPoint(pointMean);
    sum += m;
    squareSum += fixedPoint(pointMean * pointMean);
}

void OfficeTally::merge(const OfficeTally& o) {
    points += o.points;
    rays += o.rays;
    radiance += o.radiance;
    sky += o.sky;
    viewer += o.viewer;
    background += o.background;
    trapped += o.trapped;
    brightness.merge(o.brightness);
    contrast.merge(o.contrast);
    windowing.merge(o.windowing);
    pairs += o.pairs;
    switched += o.switched;
    rocks += o.rocks;
    darkRocks += o.darkRocks;
    tableRays += o.tableRays;
    tableGirdle += o.tableGirdle;
    tableDark += o.tableDark;
    tableThrough += o.tableThrough;
    centreRays += o.centreRays;
    centreDark += o.centreDark;
    centreHead += o.centreHead;
    for (int b = 0; b < kProfileBins; ++b) {
        profileRays[b] += o.profileRays[b];
        profileDark[b] += o.profileDark[b];
    }
}

OfficeTally officeView(const TraceBase& trace, const ViewerSettings& settings, RunControl* control,
                       bool& finished) {
    const Scene& scene = trace.scene();
    const Stone& stone = scene.stone();
    const double meshPerMm = scene.diameter() / trace.settings().sizeMm;
    const Observer observer(settings, meshPerMm);
    const double discRadius = axisRadius(stone);
    const double centreRadius = tableCentreRadius(stone);
    const double length = std::max(stone.bounds.extent().x, 1e-30);
    const float n = float(scene.refractiveIndex(Material::kSodiumD));
    const uint64_t streams = mix64(trace.settings().seed ^ kOfficeStreams);

    // Per turn, each tilt and its twin a sparkle step further on.
    std::vector<StonePose> poses;
    for (int a = 0; a < settings.azimuths; ++a)
        for (int k = 0; k < settings.tilts; ++k)
            for (const double step : {0.0, settings.sparkleStepDeg})
                poses.emplace_back(settings.tiltDeg(k) + step, settings.turnDeg(a));
    int faceUp = 0;
    for (int k = 1; k < settings.tilts; ++k)
        if (std::abs(settings.tiltDeg(k)) < std::abs(settings.tiltDeg(faceUp))) faceUp = k;
    const uint64_t raysPerPoint = poses.size();

    const WorkerStates<OfficeTally> workers = parallelForBlocks(
        BlockLoop{0, settings.office.points, kPointsPerBlock, trace.settings().threads}, control,
        OfficeTally{}, [&](OfficeTally& t, uint64_t first, uint64_t last) {
            for (uint64_t j = first; j < last; ++j) {
                Rng rng(streams, j);
                const double r = discRadius * std::sqrt(rng.uniformDouble()),
                             phi = 2 * M_PI * rng.uniformDouble();
                const Vec3 target(r * std::cos(phi), r * std::sin(phi), 0);
                const double pr = observer.pupilRadius() * std::sqrt(rng.uniformDouble());
                const double pphi = 2 * M_PI * rng.uniformDouble();
                const Vec3 pupil = observer.eye() + Vec3(pr * std::cos(pphi), pr * std::sin(pphi), 0);
                const Rng walk = rng;

                uint64_t rays = 0, radiance = 0, viewer = 0, background = 0;
                for (int a = 0; a < settings.azimuths; ++a) {
                    bool allOn = true, anyLit = false;
                    for (int k = 0; k < settings.tilts; ++k) {
                        std::array<bool, 2> on{}, lit{};
                        for (int twin = 0; twin < 2; ++twin) {
                            const StonePose& pose = poses[size_t((a * settings.tilts + k) * 2 + twin)];
                            const Vec3 dirWorld = normalize(pose.toWorld(target) - pupil);
                            PhotonWalker::Photon ph;
                            ph.rng = walk;
                            ViewRay ray{stone, observer, pose};
                            on[twin] = PhotonWalker::view(trace, Vec3f(pose.toStone(pupil)),
                                                          Vec3f(pose.toStone(dirWorld)), n, ray, ph);
                            allOn &= on[twin];
                            if (!on[twin]) continue;
                            lit[twin] = ray.seen == Seen::Sky;
                            ++rays;
                            radiance += fixedPoint(ray.radiance);
                            viewer += ray.seen == Seen::Viewer;
                            background += ray.seen == Seen::Background;
                            t.sky += lit[twin];
                            t.trapped += ray.seen == Seen::Trapped;
                            anyLit |= lit[twin];
                            if (k != faceUp || twin != 0) continue;
                            t.tableRays += ray.table;
                            t.tableGirdle += ray.table && ray.girdle;
                            t.tableDark += ray.table && !lit[twin];
                            t.tableThrough += ray.table && ray.seen == Seen::Background;
                            const bool centre = r < centreRadius;
                            t.centreRays += centre;
                            t.centreDark += centre && !lit[twin];
                            t.centreHead += centre && ray.head;
                            const int bin =
                                std::clamp(int((target.x / length + 0.5) * OfficeTally::kProfileBins), 0,
                                           OfficeTally::kProfileBins - 1);
                            ++t.profileRays[size_t(bin)];
                            t.profileDark[size_t(bin)] += !lit[twin];
                        }
                        if (on[0] && on[1]) {
                            ++t.pairs;
                            t.switched += lit[0] != lit[1];
                        }
                    }
                    if (allOn) {
                        ++t.rocks;
                        t.darkRocks += !anyLit;
                    }
                }
                if (rays == 0) continue;
                ++t.points;
                t.rays += rays;
                t.radiance += radiance;
                t.viewer += viewer;
                t.background += background;
                t.brightness.add(double(radiance) / kViewerScale / double(rays));
                t.contrast.add(double(viewer) / double(rays));
                t.windowing.add(double(background) / double(rays));
            }
            return (last - first) * raysPerPoint;
        });
    OfficeTally tally;
    for (const OfficeTally& t : workers.states) tally.merge(t);
    finished = workers.finished;
    return tally;
}

OfficeImage officeImage(const TraceBase& trace, const ViewerSettings& settings, int size, int samples,
                        double tiltDeg, double turnDeg, RunControl* control) {
    const Scene& scene = trace.scene();
    const Stone& stone = scene.stone();
    const Observer observer(settings, scene.diameter() / trace.settings().sizeMm);
    const StonePose pose(tiltDeg, turnDeg);
    const double half = axisRadius(stone) * 1.05;
    const float n = float(scene.refractiveIndex(Material::kSodiumD));
    const uint64_t streams = mix64(trace.settings().seed ^ kOfficeStreams ^ 0x494d414745ULL);
    const Vec3f eye(pose.toStone(observer.eye()));
    OfficeImage image;
    image.size = size;
    image.radiance.assign(size_t(size) * size_t(size), -1.0f);
    image.seen.assign(size_t(size) * size_t(size), Seen::Background);
    parallelForBlocks(
        BlockLoop{0, uint64_t(size), 1, trace.settings().threads}, control, [&](int, uint64_t y, uint64_t) {
            for (int x = 0; x < size; ++x) {
                const uint64_t pixel = y * uint64_t(size) + uint64_t(x);
                double sum = 0;
                int hits = 0;
                std::array<int, 4> seen{};
                for (int s = 0; s < samples; ++s) {
                    PhotonWalker::Photon ph;
                    ph.rng = Rng(streams, pixel * uint64_t(samples) + uint64_t(s));
                    const double px = (x + ph.rng.uniformDouble()) / size * 2 - 1;
                    const double py = 1 - (double(y) + ph.rng.uniformDouble()) / size * 2;
                    const Vec3 dir = normalize(Vec3(px * half, py * half, 0) - observer.eye());
                    ViewRay ray{stone, observer, pose};
                    if (!PhotonWalker::view(trace, eye, Vec3f(pose.toStone(dir)), n, ray, ph)) continue;
                    ++hits;
                    sum += ray.radiance;
                    ++seen[size_t(ray.seen)];
                }
                if (hits == 0) continue;
                image.radiance[pixel] = float(sum / hits);
                image.seen[pixel] = Seen(std::max_element(seen.begin(), seen.end()) - seen.begin());
            }
            return uint64_t(size);
        });
    return image;
}

}  // namespace facetlight
