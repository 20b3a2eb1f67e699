#include "viewer/polariscope.h"

#include <algorithm>
#include <cmath>

#include "scene/scene.h"
#include "trace/photon_walker.h"
#include "util/error.h"
#include "util/parallel.h"

namespace facetlight {
namespace {

// The analyser's random draws: a stream apart from the photons' (seed and index mixed with a constant).
constexpr uint64_t kAnalyserStream = 0x9e3779b97f4a7c15ULL;
// Under a light box the eye above the analyser takes the light leaving within this angle of the vertical: a
// gemmologist looks straight down, and light leaving obliquely (which a diffuse lamp sends out in every
// direction) misses the eye. The parallel beam's light is counted wherever it leaves upward, as before.
constexpr double kEyeConeDeg = 15;

// Counts what leaves the stone upward and what the analyser (axis across the vertical) passes of it.
struct AnalyserCount {
    Vec3f axis;
    float minUp = 0;  // the smallest d.z of light the eye takes
    uint64_t seed = 0, index = 0;
    uint64_t upward = 0, passed = 0;
    Polarization state;
    // The picture: the turn (cos, sin) that shows the stone as turned, the radius the cells span, the cells.
    float turnCos = 1, turnSin = 0, radius = 1;
    int size = 0;
    std::vector<uint32_t>* seen = nullptr;

    void wavelength(float) {}
    void missed() {}
    void reflectedAtEntry(uint32_t, const Vec3f&, const Vec3f&) {}
    void entered(uint32_t) {}
    void internalReflection(uint32_t) {}
    void exitPolarization(const Polarization& p, const Vec3f&) { state = p; }
    void exited(uint32_t, const Vec3f& p, const Vec3f& d, uint32_t) {
        if (!(d.z > minUp)) return;
        ++upward;
        Rng draw(seed ^ kAnalyserStream, index);
        if (!(draw.uniform() < analyserShare(state, d, frameAcross(d, axis)))) return;
        ++passed;
        if (size == 0) return;
        const float x = turnCos * p.x - turnSin * p.y, y = turnSin * p.x + turnCos * p.y;
        const int col = int((x / radius + 1) * 0.5f * float(size)), row = int((1 - y / radius) * 0.5f * float(size));
        if (col >= 0 && col < size && row >= 0 && row < size) ++(*seen)[size_t(row) * size_t(size) + size_t(col)];
    }
    void trapped(uint32_t) {}
    void lost(uint32_t) {}
    void absorbed(uint32_t) {}
};

}  // namespace

const settings::Schema<PolariscopeSettings>& polariscopeSettingsSchema() {
    using namespace settings;
    static const Schema<PolariscopeSettings> schema({
        count("angles", &PolariscopeSettings::angles, 4, 360,
              {"--angles", "Polariscope: turntable positions over half a turn"}),
        count("photons", &PolariscopeSettings::photons, 100, 10'000'000,
              {"--polariscope-photons", "Polariscope: photons per position"}),
        count("picture_size", &PolariscopeSettings::pictureSize, 0, 1024,
              {"--polariscope-picture", "Polariscope: pixels across the view from above (0: none)"}),
        choice("lamp", &PolariscopeSettings::lamp, kPolariscopeLampNames,
               {"--polariscope-lamp",
                "Polariscope: the light below the lower filter, a parallel beam straight up (collimated) or a "
                "diffusing light box (diffuse: the same radiance from every direction below)"}),
    });
    return schema;
}

double PolariscopeReading::shareStderr() const {
    const double p = share();
    return upward ? std::sqrt(p * (1 - p) / double(upward)) : 0;
}

Polariscope polariscope(const Stone& stone, const TraceSettings& settings, const PolariscopeSettings& p,
                        RunControl* control) {
    polariscopeSettingsSchema().read(polariscopeSettingsSchema().write(p));  // the table's checks
    double radius = 0;  // the stone's largest horizontal distance from its axis, the picture's half-width
    for (const Vec3& v : stone.vertices) radius = std::max(radius, std::hypot(v.x, v.y));
    Polariscope out;
    out.readings.resize(size_t(p.angles));
    const BlockLoop loop{0, uint64_t(p.angles), 1, settings.threads};
    parallelForBlocks(loop, control, [&](int, uint64_t first, uint64_t last) {
        for (uint64_t k = first; k < last; ++k) {
            const double angle = 180.0 * double(k) / p.angles;
            // Turning the stone by `angle` is turning both filters by -angle.
            const double polarizer = std::fmod(360.0 - angle, 180.0);
            TraceSettings s = settings;
            s.polarization = PolarizationMode::On;
            s.light = LightSettings{};
            if (p.lamp == PolariscopeLamp::Collimated) {
                s.light.direction = {0, 0, 1};
                s.light.polarizerDeg = polarizer;
            } else {
                // The uniform dome turned upside down (the world turned half a turn about x): its light comes
                // from below. The polariser's axis is given in that world, whose y is the stone's -y.
                s.light.model = LightModelKind::Hemisphere;
                s.light.tiltDeg = 180;
                s.light.polarizerDeg = std::fmod(180.0 - polarizer, 180.0);
            }
            s.fire.enabled = false;
            const Scene scene(stone, s);
            const TraceBase trace(scene, s);
            const double a = radians(polarizer + 90);
            PolariscopeReading& reading = out.readings[k];
            reading.seen.assign(size_t(p.pictureSize) * size_t(p.pictureSize), 0);
            const float minUp =
                p.lamp == PolariscopeLamp::Diffuse ? float(std::cos(radians(kEyeConeDeg))) : 0.0f;
            AnalyserCount count{Vec3f(float(std::cos(a)), float(std::sin(a)), 0),
                                minUp,
                                s.seed,
                                0,
                                0,
                                0,
                                {},
                                float(std::cos(radians(angle))),
                                float(std::sin(radians(angle))),
                                float(1.05 * radius),
                                p.pictureSize,
                                &reading.seen};
            for (uint64_t i = 0; i < p.photons; ++i) {
                count.index = i;
                if (scene.convex()) {
                    PhotonWalker::walk(trace, *scene.convex(), i, count);
                } else {
                    PhotonWalker::walk(trace, *scene.embree(), i, count);
                }
            }
            reading.angleDeg = angle;
            reading.upward = count.upward;
            reading.passed = count.passed;
        }
        return (last - first) * p.photons;
    });
    // Dark positions over a whole turn: the half turn's minima and the same 180 deg on. A stone's two waves
    // vibrate at right angles, so its dark positions lie 90 deg apart: a dark one is the least reading within
    // 45 deg either way (the first of equals), not any local minimum, which the readings' noise makes many of
    // (a sapphire brilliant at 360 angles of 300 photons listed 42 dark positions).
    const auto brightest = std::max_element(out.readings.begin(), out.readings.end(),
                                            [](const auto& a, const auto& b) { return a.share() < b.share(); });
    const size_t n = out.readings.size();
    auto leastNearby = [&](size_t k) {
        for (size_t j = 0; j < n; ++j) {
            const double apart = std::fabs(out.readings[j].angleDeg - out.readings[k].angleDeg);
            const double share = out.readings[j].share(), own = out.readings[k].share();
            if (j != k && std::min(apart, 180 - apart) <= 45 && (share < own || (share == own && j < k)))
                return false;
        }
        return true;
    };
    auto clearlyUnder = [&](const PolariscopeReading& r, double share) {
        return r.share() < share &&
               brightest->share() - r.share() > 5 * std::hypot(brightest->shareStderr(), r.shareStderr());
    };
    // It blinks when its darkest reading is under half the brightest; then each dark position is nearer the
    // darkest than the brightest (half the brightest for each split a zircon brilliant's pair, 19.9 against
    // 18.5 % with 39.4 % between, into one dark position every half turn).
    const auto darkest = std::min_element(out.readings.begin(), out.readings.end(),
                                          [](const auto& a, const auto& b) { return a.share() < b.share(); });
    if (darkest != out.readings.end() && clearlyUnder(*darkest, 0.5 * brightest->share()))
        for (size_t k = 0; k < n; ++k)
            if (leastNearby(k) &&
                clearlyUnder(out.readings[k], 0.5 * (darkest->share() + brightest->share()))) {
                out.darkAnglesDeg.push_back(out.readings[k].angleDeg);
                out.reaction = PolariscopeReaction::Blinks;
            }
    if (!out.blinks() && brightest != out.readings.end() && brightest->share() >= kStaysDarkShare)
        out.reaction = PolariscopeReaction::StaysLight;
    for (size_t k = 0, dark = out.darkAnglesDeg.size(); k < dark; ++k)
        out.darkAnglesDeg.push_back(out.darkAnglesDeg[k] + 180);
    return out;
}

nlohmann::json toJson(const Polariscope& p) {
    nlohmann::json readings = nlohmann::json::array();
    for (const PolariscopeReading& r : p.readings)
        readings.push_back({{"angle_deg", r.angleDeg},
                            {"share", r.share()},
                            {"share_stderr", r.shareStderr()},
                            {"upward", r.upward},
                            {"passed", r.passed}});
    return {{"readings", readings},
            {"dark_angles_deg", p.darkAnglesDeg},
            {"blinks", p.blinks()},
            {"reaction", kPolariscopeReactionNames.name(p.reaction)}};
}

}  // namespace facetlight
