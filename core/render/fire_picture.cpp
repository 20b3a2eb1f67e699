#include "render/fire_picture.h"

#include <algorithm>
#include <cmath>

#include "colour/colour_space.h"
#include "optics/spectrum.h"
#include "render/camera.h"
#include "render/detail/sample_tracer.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/random.h"

namespace facetlight {
namespace {

// Keeps the picture's random streams apart from the tracer's, the renderer's and the ASET view's.
constexpr uint64_t kFireStreams = 0x46495245504943ULL;

// The XYZ of an equal-energy spectrum of unit spectral radiance over the traced range (midpoint rule, steps
// of 0.1 nm).
Vec3 equalEnergyXyz() {
    constexpr int kSteps = int(10 * (kFireMaxWavelength - kFireMinWavelength));
    Vec3 sum;
    for (int i = 0; i < kSteps; ++i) sum += cieXyz(kFireMinWavelength + (i + 0.5) * 0.1);
    return sum * 0.1;
}

const Vec3& equalEnergySrgb() {
    static const Vec3 white = xyzToLinearSrgb(equalEnergyXyz());
    return white;
}

// One small bright light in a dim room, nothing under the stone.
class Spotlight {
  public:
    Spotlight(const Scene& scene, const FirePictureSettings& s, const Vec3& toViewer)
        : scene_(scene),
          toLight_(
              scene.toStone(Vec3{0, -std::sin(radians(s.lightTiltDeg)), std::cos(radians(s.lightTiltDeg))})),
          cosRadius_(std::cos(radians(s.lightRadiusDeg))),
          // A disc of radiance L and angular radius r gives irradiance pi L sin^2 r on a plane facing it.
          lamp_(1 / (kPi * std::pow(std::sin(radians(s.lightRadiusDeg)), 2))),
          ambient_(s.ambient),
          toViewer_(toViewer) {}

    bool stoneFirst(const Vec3&, const Vec3&, double) const { return true; }

    Vec3 radiance(const Vec3&, const Vec3& dir, const Vec3& colour, double weight, Rng&) const {
        double l = ambient_ * Scene::environment(scene_.toWorld(dir), toViewer_);
        if (dot(dir, toLight_) >= cosRadius_) l += lamp_;
        return colour * (weight * l);
    }

  private:
    const Scene& scene_;
    Vec3 toLight_;  // stone frame
    double cosRadius_, lamp_, ambient_;
    Vec3 toViewer_;  // world
};

double luminance(const Vec3& rgb) {
    return 0.2126 * rgb.x + 0.7152 * rgb.y + 0.0722 * rgb.z;  // IEC 61966-2-1 (the Y row of its matrix)
}

}  // namespace

Vec3 balancedSrgb(const Vec3& xyz) {
    const Vec3 rgb = xyzToLinearSrgb(xyz);
    const Vec3& white = equalEnergySrgb();
    return {rgb.x / white.x, rgb.y / white.y, rgb.z / white.z};
}

FirePicture firePicture(const Scene& scene, const RenderSettings& render, const FirePictureSettings& settings,
                        int threads, uint64_t seed, RunControl* control) {
    firePictureSettingsSchema().read(nlohmann::json(toJson(settings)), "fire_picture");
    const Vec3 target = scene.toWorld(scene.center());
    const Camera camera(render.camera, target, scene.diameter(), render.width, render.height);
    const Vec3 eye = scene.toStone(camera.position());
    const Spotlight spotlight(scene, settings, normalize(camera.position() - target));
    const int count = settings.wavelengths;
    const double stratum = (kFireMaxWavelength - kFireMinWavelength) / count;
    // A path that never depends on the wavelength sees the light's whole spectrum, in one sample's share.
    const Vec3 white = equalEnergyXyz() * (1.0 / count);
    const double fixedIndex = scene.refractiveIndex(Material::kSodiumD);
    const uint64_t streams = mix64(seed ^ kFireStreams);
    const int width = render.width, height = render.height;

    FirePicture picture;
    picture.width = width;
    picture.height = height;
    picture.xyz.assign(size_t(width) * size_t(height), Vec3{});
    const bool finished = parallelForBlocks(
        BlockLoop{0, uint64_t(height), 1, threads}, control, [&](int, uint64_t y, uint64_t) {
            for (int x = 0; x < width; ++x) {
                const uint64_t pixel = y * uint64_t(width) + uint64_t(x);
                Rng rng(streams, pixel);
                detail::SampleTracer tracer(scene, render.maxDepth, spotlight, rng);
                Vec3 sum;
                for (int s = 0; s < count; ++s) {
                    const double px = x + rng.uniformDouble(), py = double(y) + rng.uniformDouble();
                    const double wavelength = kFireMinWavelength + (s + rng.uniformDouble()) * stratum;
                    const double n = scene.dispersive() ? scene.refractiveIndex(wavelength) : fixedIndex;
                    const Vec3 dir = scene.toStone(camera.direction(px, py));
                    sum += tracer.trace(eye, dir, n, cieXyz(wavelength) * stratum, white);
                }
                picture.xyz[pixel] = sum;
            }
            return uint64_t(width);
        });
    picture.cancelled = !finished;
    return picture;
}

Image toDisplay(const FirePicture& picture) {
    std::vector<Vec3> rgb(picture.xyz.size());
    std::vector<double> lit;
    for (size_t i = 0; i < rgb.size(); ++i) {
        rgb[i] = balancedSrgb(picture.xyz[i]);
        if (const double y = luminance(rgb[i]); y > 0) lit.push_back(y);
    }
    double exposure = 1;
    if (!lit.empty()) {
        const size_t k = std::min(lit.size() - 1, size_t(double(lit.size()) * kFireExposurePercentile / 100));
        std::nth_element(lit.begin(), lit.begin() + ptrdiff_t(k), lit.end());
        if (lit[k] > 0) exposure = kFireExposureLevel / lit[k];
    }
    Image image(picture.width, picture.height);
    for (int y = 0; y < picture.height; ++y) {
        for (int x = 0; x < picture.width; ++x) {
            const Vec3& p = rgb[size_t(y) * size_t(picture.width) + size_t(x)];
            Vec3 c{std::max(0.0, p.x), std::max(0.0, p.y), std::max(0.0, p.z)};
            c = c * exposure;
            if (const double top = std::max({c.x, c.y, c.z}); top > 1) c = c * (1 / top);
            image.at(x, y) = {float(srgbEncode(c.x)), float(srgbEncode(c.y)), float(srgbEncode(c.z))};
        }
    }
    return image;
}

}  // namespace facetlight
