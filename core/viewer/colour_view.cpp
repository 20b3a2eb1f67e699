#include "viewer/colour_view.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "optics/spectrum.h"
#include "scene/scene.h"
#include "trace/photon_walker.h"
#include "trace/trace_base.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/random.h"

namespace facetlight {
namespace {

// Keeps the view's random streams apart from the tracer's and the other views' under the same job seed.
constexpr uint64_t kColourStreams = 0x434f4c52ULL;
constexpr double kSpanNm = kCieLastNm - kCieFirstNm;

// The illuminant's spectrum against the colour matching functions over 380-780 nm, by the midpoint rule at
// 0.05 nm: the integrals the view's rays estimate, so that the dome seen directly has Y = 1 exactly.
Vec3 illuminantIntegral(Illuminant illuminant) {
    constexpr double step = 0.05;
    Vec3 sum;
    for (double l = kCieFirstNm + step / 2; l < kCieLastNm; l += step)
        sum += cieXyz(l) * (illuminantPower(illuminant, l) * step);
    return sum;
}

// The light a direction leaving the stone (stone frame) brings: the dome's 1, the head cone's 0, the ground's
// reflectance below the horizon.
class Dome {
  public:
    Dome(const Scene& scene, const ColourSettings& c)
        : scene_(scene), cosHead_(std::cos(radians(c.headConeDeg))), ground_(c.ground) {}
    bool below(const Vec3f& d) const { return scene_.toWorld(Vec3{d.x, d.y, d.z}).z < 0; }
    double radiance(const Vec3f& d) const {
        const Vec3 w = scene_.toWorld(Vec3{d.x, d.y, d.z});
        if (w.z < 0) return ground_;
        return w.z >= cosHead_ ? 0.0 : 1.0;
    }

  private:
    const Scene& scene_;
    double cosHead_, ground_;
};

// What a view ray (PhotonWalker::view) brings back: the light of the direction it leaves in, and the optical
// depth alpha L it crossed inside (weighted, not drawn: no ray is lost to absorption, so the colour's noise
// is the facet choices' alone).
struct ColourRay {
    const Dome& dome;
    double radiance = 0;
    float depth = 0;
    bool windowed = false;
    void reflectedAtEntry(uint32_t, const Vec3f&, const Vec3f& d) { radiance = dome.radiance(d); }
    void entered(uint32_t) {}
    void exited(uint32_t, const Vec3f&, const Vec3f& d, uint32_t) {
        radiance = dome.radiance(d);
        windowed = dome.below(d);
    }
    void internalReflection(uint32_t) {}
    void trapped(uint32_t) { radiance = 0; }
    void lost(uint32_t) { radiance = 0; }
    void attenuated(float alphaL) { depth += alphaL; }
};

// `count` may be fractional: a path counts by the share of its wavelengths that did it. Its binomial error
// over the paths is then an upper bound (a share in [0, 1] varies no more than a 0-or-1 outcome of its mean).
ColourShare binomial(double count, uint64_t n) {
    if (n == 0) return {};
    const double p = count / double(n);
    return {p, std::sqrt(p * (1 - p) / double(n))};
}

// Mean and spread over n pixels from their sum and sum of squares: the pixels taken as n samples of the
// face-up area, the mean's error spread / sqrt(n) and the spread's spread / sqrt(2 (n - 1)) (normal theory).
class Moments {
  public:
    void add(double v) {
        ++n_;
        sum_ += v;
        squares_ += v * v;
    }
    ColourFigure figure() const {
        if (n_ == 0) return {};
        const double n = double(n_), mean = sum_ / n;
        const double sd = n_ > 1 ? std::sqrt(std::max(0.0, (squares_ - n * mean * mean) / (n - 1))) : 0;
        return {mean, sd / std::sqrt(n), sd, n_ > 1 ? sd / std::sqrt(2 * (n - 1)) : 0};
    }

  private:
    uint64_t n_ = 0;
    double sum_ = 0, squares_ = 0;
};

}  // namespace

const settings::Schema<ColourSettings>& colourSettingsSchema() {
    using namespace settings;
    static const Schema<ColourSettings> schema({
        count("picture_size", &ColourSettings::pictureSize, 16, 1024,
              {"--colour-picture", "Colour view: pixels across the face-up view"}),
        count("samples", &ColourSettings::samples, 1, 256,
              {"--colour-samples", "Colour view: view paths per pixel"}),
        count("wavelengths", &ColourSettings::wavelengths, 4, 100,
              {"--colour-wavelengths",
               "Colour view: each path traced at one wavelength in each of this many strata of 380-780 nm"}),
        choice(
            "illuminant", &ColourSettings::illuminant, kIlluminantNames,
            {"--illuminant", "Colour view: the CIE illuminant of the dome (D65 daylight or A incandescent)"}),
        number("head_cone_deg", &ColourSettings::headConeDeg, {.lo = 0, .hi = 60},
               {"--colour-head-cone", "Colour view: the viewer's head, a dark cone around the zenith",
                "degrees"}),
        number("ground", &ColourSettings::ground, {.lo = 0, .hi = 1},
               {"--colour-ground",
                "Colour view: the ground's reflectance under the dome (1 a white tray, 0 black)"}),
        number("extinct_below_l", &ColourSettings::extinctBelowL, {.lo = 0, .hi = 100},
               {"--extinct-below", "Colour view: a pixel darker than this CIELAB L* counts as extinct"}),
        number("saturated_above_c", &ColourSettings::saturatedAboveC, {.lo = 0, .hi = 200},
               {"--saturated-above", "Colour view: a pixel of larger chroma C*ab counts as saturated"}),
    });
    return schema;
}

ColourView colourView(const Stone& stone, const TraceSettings& settings, const ColourSettings& c,
                      RunControl* control) {
    colourSettingsSchema().read(colourSettingsSchema().write(c));  // the table's checks
    TraceSettings s = settings;
    s.light = LightSettings{};  // the view's own dome, the stone face-up
    s.fire.enabled = false;
    const Scene scene(stone, s);
    const TraceBase trace(scene, s);

    ColourView out;
    out.illuminant = c.illuminant;
    out.sizeMm = s.sizeMm;
    out.headConeDeg = c.headConeDeg;
    out.ground = c.ground;
    out.extinctBelowL = c.extinctBelowL;
    out.saturatedAboveC = c.saturatedAboveC;
    out.absorbs = trace.absorbs();
    const Vec3 integral = illuminantIntegral(c.illuminant);
    out.white = integral / integral.y;

    // Face-up, orthographic: along -z of the world, the picture's axes the world's x and y.
    const Vec3 view = scene.toStone({0, 0, -1}), u = scene.toStone({1, 0, 0}), v = scene.toStone({0, 1, 0});
    const Vec3 centre = scene.center();
    double half = 0;
    for (const Vec3& p : stone.vertices)
        half = std::max({half, std::abs(dot(p - centre, u)), std::abs(dot(p - centre, v))});
    half *= 1.05;
    const size_t n = size_t(c.pictureSize);
    out.size = c.pictureSize;
    out.samples = c.samples;
    out.wavelengths = c.wavelengths;
    out.halfWidthMm = half * s.sizeMm / scene.diameter();
    out.xyz.assign(n * n, Vec3{});
    out.stoneRays.assign(n * n, 0);
    std::vector<uint16_t> windowed(n * n, 0);

    const Dome dome(scene, c);
    const Vec3f dir(view);
    const uint64_t streams = mix64(settings.seed ^ kColourStreams);
    const double scale = kSpanNm / integral.y;
    const BlockLoop loop{0, n, 4, settings.threads};
    out.cancelled = !parallelForBlocks(loop, control, [&](int, uint64_t first, uint64_t last) {
        for (uint64_t row = first; row < last; ++row)
            for (size_t col = 0; col < n; ++col) {
                const size_t k = row * n + col;
                Vec3 sum;
                for (int sample = 0; sample < c.samples; ++sample) {
                    const uint64_t stream = uint64_t(k) * uint64_t(c.samples) + uint64_t(sample);
                    Rng rng(streams, stream);
                    const double x = (2 * (double(col) + rng.uniformDouble()) / double(n) - 1) * half;
                    const double y = (1 - 2 * (double(row) + rng.uniformDouble()) / double(n)) * half;
                    const double offset = rng.uniformDouble();  // the strata's shared place within each
                    const Vec3f eye(centre + u * x + v * y - view * (3 * half));
                    bool met = false;
                    for (int w = 0; w < c.wavelengths; ++w) {
                        const double l = kCieFirstNm + kSpanNm * (w + offset) / c.wavelengths;
                        PhotonWalker::Photon ph;
                        ph.rng = rng;  // every wavelength the same draws from here on
                        ph.setAbsorption(trace, float(l));
                        const float index =
                            scene.dispersive() ? float(scene.material().index(l)) : scene.fixedIndex();
                        ColourRay ray{dome};
                        if (!PhotonWalker::view(trace, eye, dir, index, ray, ph)) break;
                        met = true;
                        windowed[k] += ray.windowed ? 1 : 0;
                        const double light = ray.radiance * std::exp(-double(ray.depth));
                        sum += cieXyz(l) * (illuminantPower(c.illuminant, l) * light * scale);
                    }
                    out.stoneRays[k] += met ? 1 : 0;
                }
                out.xyz[k] = sum / double(c.samples * c.wavelengths);
            }
        return (last - first) * n;
    });

    Moments L, a, b, chroma;
    uint64_t windowedRays = 0, extinct = 0, saturated = 0;
    for (size_t k = 0; k < n * n; ++k) {
        if (!out.onStone(k)) continue;
        ++out.pixels;
        out.rays += uint64_t(out.stoneRays[k]) * uint64_t(c.wavelengths);
        windowedRays += windowed[k];
        out.meanXyz += out.xyz[k];
        const Lab lab = out.lab(k);
        L.add(lab.L);
        a.add(lab.a);
        b.add(lab.b);
        chroma.add(lab.chroma());
        extinct += lab.L < c.extinctBelowL ? 1 : 0;
        saturated += lab.chroma() > c.saturatedAboveC ? 1 : 0;
    }
    if (out.pixels > 0) out.meanXyz = out.meanXyz / double(out.pixels);
    out.meanLab = xyzToLab(out.meanXyz, out.white);
    out.L = L.figure();
    out.a = a.figure();
    out.b = b.figure();
    out.chroma = chroma.figure();
    const uint64_t paths = out.rays / uint64_t(c.wavelengths);
    out.windowed = binomial(double(windowedRays) / c.wavelengths, paths);
    out.extinct = binomial(double(extinct), out.pixels);
    out.saturated = binomial(double(saturated), out.pixels);
    return out;
}

nlohmann::json toJson(const ColourView& view) {
    auto figure = [](const ColourFigure& f) {
        return nlohmann::json{{"mean", f.mean},
                              {"mean_stderr", f.meanError},
                              {"spread", f.spread},
                              {"spread_stderr", f.spreadError}};
    };
    auto share = [](const ColourShare& s) {
        return nlohmann::json{{"share", s.share}, {"stderr", s.standardError}};
    };
    const Vec3 rgb = xyzToLinearSrgb(view.meanXyz);
    auto byte = [](double linear) { return int(std::lround(255 * srgbEncode(linear))); };
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", byte(rgb.x), byte(rgb.y), byte(rgb.z));
    return {{"illuminant", std::string(kIlluminantNames.name(view.illuminant))},
            {"white_xyz", {view.white.x, view.white.y, view.white.z}},
            {"size_mm", view.sizeMm},
            {"absorbs", view.absorbs},
            {"head_cone_deg", view.headConeDeg},
            {"ground", view.ground},
            {"picture_size", view.size},
            {"samples", view.samples},
            {"wavelengths", view.wavelengths},
            {"pixels", view.pixels},
            {"rays", view.rays},
            {"L", figure(view.L)},
            {"a", figure(view.a)},
            {"b", figure(view.b)},
            {"chroma", figure(view.chroma)},
            {"mean_colour",
             {{"xyz", {view.meanXyz.x, view.meanXyz.y, view.meanXyz.z}},
              {"L", view.meanLab.L},
              {"a", view.meanLab.a},
              {"b", view.meanLab.b},
              {"chroma", view.meanLab.chroma()},
              {"hue_deg", view.meanLab.hueDeg()},
              {"srgb", hex}}},
            {"windowed", share(view.windowed)},
            {"extinct", share(view.extinct)},
            {"extinct_below_l", view.extinctBelowL},
            {"saturated", share(view.saturated)},
            {"saturated_above_c", view.saturatedAboveC}};
}

}  // namespace facetlight
