#pragma once
// The picture of the stone: rays from the camera, reflected and refracted by the stone's facets with Fresnel
// weights and total internal reflection, each sample on its own wavelength band (dispersion), ending in the
// studio environment or on the floor, whose light comes from the direct light and the caustic photon map.
//
// Threads pull 16 x 16 tiles from a shared counter; pixel p draws its random numbers from Rng(seed, p) alone,
// so the image is the same bits for any thread count.
#include <atomic>
#include <cstdint>
#include <vector>

#include "camera.h"
#include "geometry.h"
#include "image.h"
#include "photon_map.h"
#include "render_settings.h"
#include "scene.h"

namespace facetlight {

struct RenderControl {
    std::atomic<uint64_t>* pixelsDone = nullptr;  // advanced after each tile
    const std::atomic<bool>* cancel = nullptr;    // checked before each tile
};

// Linear sRGB radiance per pixel, row by row from the top.
struct RenderedImage {
    int width = 0, height = 0;
    std::vector<Vec3> pixels;
    bool cancelled = false;
};

// The caustic map may be empty (no photon reached the floor). Throws Error on bad settings.
RenderedImage render(const Scene& scene, const PhotonMap& caustics, const RenderSettings& settings,
                     int threads, uint64_t seed, const RenderControl& control = {});

// The display image: exposure, a soft shoulder for highlights, the sRGB curve.
Image toDisplay(const RenderedImage& image);

// The k of the caustic density estimate.
constexpr int kCausticNeighbors = 64;

}  // namespace facetlight
