#include "render/aset.h"

#include <algorithm>
#include <cmath>

#include "geometry/rotation.h"
#include "render/camera.h"
#include "trace/photon_walker.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/random.h"

namespace facetlight {
namespace {

// Keeps the view's random streams apart from the tracer's and the renderer's under the same job seed.
constexpr uint64_t kAsetStreams = 0x41534554ULL;

// The world as the view sees it: the scene's frame turned by a StoneTurn.
class TurnedFrame {
  public:
    TurnedFrame(const Scene& scene, const StoneTurn& turn)
        : scene_(scene),
          axis_(std::cos(radians(turn.axisDeg)), std::sin(radians(turn.axisDeg)), 0),
          cos_(std::cos(radians(turn.deg))),
          sin_(std::sin(radians(turn.deg))) {}

    Vec3 toWorld(const Vec3& v) const { return rotateAbout(scene_.toWorld(v), axis_, cos_, sin_); }
    Vec3 toStone(const Vec3& v) const { return scene_.toStone(rotateAbout(v, axis_, cos_, -sin_)); }

  private:
    const Scene& scene_;
    Vec3 axis_;
    double cos_, sin_;
};

// Classes a direction outside the stone (stone frame) by where it points in the world.
class SkyBands {
  public:
    SkyBands(const TurnedFrame& frame, const AsetSettings& s, const Vec3& toViewer)
        : frame_(frame),
          toViewer_(toViewer),
          cosHead_(std::cos(radians(s.headConeDeg))),
          sinLow_(std::sin(radians(s.lowBelowDeg))) {}

    AsetClass operator()(const Vec3f& dir) const {
        const Vec3 w = frame_.toWorld(Vec3{dir.x, dir.y, dir.z});
        if (w.z < 0) return AsetClass::Leakage;
        if (dot(w, toViewer_) >= cosHead_) return AsetClass::Head;
        return w.z >= sinLow_ ? AsetClass::Bright : AsetClass::Low;
    }

  private:
    const TurnedFrame& frame_;
    Vec3 toViewer_;
    double cosHead_, sinLow_;
};

// What a view ray (PhotonWalker::view) reports, kept as the ray's class.
struct ViewRayEnd {
    const SkyBands& bands;
    AsetClass end = AsetClass::Trapped;
    void reflectedAtEntry(uint32_t, const Vec3f&, const Vec3f& dir) { end = bands(dir); }
    void entered(uint32_t) {}
    void exited(uint32_t, const Vec3f&, const Vec3f& dir, uint32_t) { end = bands(dir); }
    void internalReflection(uint32_t) {}
    void trapped(uint32_t) { end = AsetClass::Trapped; }
    void lost(uint32_t) { end = AsetClass::Trapped; }
    void absorbed(uint32_t) { end = AsetClass::Trapped; }  // dark, as trapped light
};

AsetShare binomialShare(uint64_t count, uint64_t n) {
    if (n == 0) return {};
    const double p = double(count) / double(n);
    return {p, std::sqrt(p * (1 - p) / double(n))};
}

}  // namespace

std::string_view asetClassName(AsetClass c) {
    switch (c) {
        case AsetClass::Head:
            return "head";
        case AsetClass::Bright:
            return "bright";
        case AsetClass::Low:
            return "low";
        case AsetClass::Leakage:
            return "leakage";
        case AsetClass::Trapped:
            return "trapped";
    }
    return "";
}

uint64_t AsetView::stoneRays() const {
    uint64_t n = 0;
    for (uint64_t t : totals) n += t;
    return n;
}

AsetShare AsetView::share(AsetClass c) const {
    return binomialShare(totals[size_t(c)], stoneRays());
}

bool AsetView::onStone(size_t pixel) const {
    const auto& c = counts[pixel];
    return std::any_of(c.begin(), c.end(), [](uint8_t k) { return k > 0; });
}

bool AsetView::lit(size_t pixel) const {
    const auto& c = counts[pixel];
    const int lit = c[size_t(AsetClass::Bright)] + c[size_t(AsetClass::Low)];
    const int dark =
        c[size_t(AsetClass::Head)] + c[size_t(AsetClass::Leakage)] + c[size_t(AsetClass::Trapped)];
    return lit > dark;
}

AsetView asetView(const TraceBase& trace, const CameraSettings& cameraSettings, int width, int height,
                  const AsetSettings& settings, int threads, uint64_t seed, RunControl* control,
                  const StoneTurn& turn) {
    const Scene& scene = trace.scene();
    settings.validate();
    if (width < kMinImageSide || width > kMaxImageSide || height < kMinImageSide || height > kMaxImageSide) {
        throw Error("render.width", "an ASET view's sides must be between " + std::to_string(kMinImageSide) +
                                        " and " + std::to_string(kMaxImageSide) + " pixels");
    }
    const TurnedFrame frame(scene, turn);
    const Vec3 target = frame.toWorld(scene.center());
    const Camera camera(cameraSettings, target, scene.diameter(), width, height);
    const SkyBands bands(frame, settings, normalize(camera.position() - target));
    const Vec3f eye(frame.toStone(camera.position()));
    const float n = float(scene.refractiveIndex(Material::kSodiumD));
    const uint64_t streams = mix64(seed ^ kAsetStreams);

    AsetView view;
    view.width = width;
    view.height = height;
    view.samples = settings.samples;
    view.counts.assign(size_t(width) * size_t(height), {});
    using Totals = std::array<uint64_t, kAsetClasses>;
    const WorkerStates<Totals> workers = parallelForBlocks(
        BlockLoop{0, uint64_t(height), 1, threads}, control, Totals{},
        [&](Totals& totals, uint64_t y, uint64_t) {
            for (int x = 0; x < width; ++x) {
                const uint64_t pixel = y * uint64_t(width) + uint64_t(x);
                auto& counts = view.counts[pixel];
                for (int s = 0; s < settings.samples; ++s) {
                    PhotonWalker::Photon ph;
                    ph.rng = Rng(streams, pixel * uint64_t(settings.samples) + uint64_t(s));
                    const double px = x + ph.rng.uniformDouble(), py = double(y) + ph.rng.uniformDouble();
                    const Vec3f dir(frame.toStone(camera.direction(px, py)));
                    ViewRayEnd ray{bands};
                    if (!PhotonWalker::view(trace, eye, dir, n, ray, ph)) continue;
                    ++counts[size_t(ray.end)];
                    ++totals[size_t(ray.end)];
                }
            }
            return uint64_t(width);
        });
    for (const Totals& t : workers.states) {
        for (int c = 0; c < kAsetClasses; ++c) view.totals[c] += t[c];
    }
    view.cancelled = !workers.finished;
    return view;
}

nlohmann::json toJson(const AsetView& view, const AsetSettings& settings) {
    nlohmann::json shares = nlohmann::json::object();
    for (int c = 0; c < kAsetClasses; ++c) {
        const AsetShare s = view.share(AsetClass(c));
        shares[std::string(asetClassName(AsetClass(c)))] = {{"share", s.share}, {"stderr", s.standardError}};
    }
    return {{"settings", toJson(settings)},
            {"width", view.width},
            {"height", view.height},
            {"rays", view.stoneRays()},
            {"shares", shares}};
}

}  // namespace facetlight
