#pragma once
// The picture of the stone: rays from the camera, reflected and refracted by the stone's facets with Fresnel
// weights and total internal reflection, each sample on its own wavelength band (dispersion), ending in the
// studio environment or on the floor, whose light comes from the direct light and the caustic photon map.
//
// Workers claim 16 x 16 tiles from parallelForBlocks; pixel p draws its random numbers from Rng(seed, p)
// alone, so the image is the same bits for any thread count.
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/geometry.h"
#include "image/image.h"
#include "photonmap/photon_map.h"
#include "render/camera.h"
#include "render/render_settings.h"
#include "scene/scene.h"
#include "util/distributed.h"
#include "util/run_control.h"

namespace facetlight {

// Linear sRGB radiance per pixel, row by row from the top.
struct RenderedImage {
    int width = 0, height = 0;
    std::vector<Vec3> pixels;
    bool cancelled = false;
};

// The tiles a render covers: tile t (16 x 16 pixels, numbered row by row from the top left) when
// t % stride == offset. Rank r of R renders {r, R}: dealt round-robin, the costly tiles over the stone spread
// evenly across the ranks.
struct TileShare {
    int offset = 0, stride = 1;
};

// The caustic map may be empty (no photon reached the floor). Pixels outside `share` stay zero. Advances
// control->done() by the pixels of each tile rendered. Throws Error on bad settings.
RenderedImage render(const Scene& scene, const PhotonMap& caustics, const RenderSettings& settings,
                     int threads, uint64_t seed, RunControl* control = nullptr, TileShare share = {});

// The render spread over the ranks of `comm` (docs/distributed.md): each rank renders its TileShare and
// rank 0 receives the whole image, the single-process one bit for bit; the other ranks keep their own tiles.
// `cancelled` is true on every rank when any rank was cancelled. control->done() counts this rank's pixels.
RenderedImage render(Communicator& comm, const Scene& scene, const PhotonMap& caustics,
                     const RenderSettings& settings, int threads, uint64_t seed,
                     RunControl* control = nullptr);

// The pixels of a share: how many, and their values tile by tile in tile order (row by row within a tile),
// taken from or put back into a full-size image.
uint64_t sharePixelCount(int width, int height, TileShare share);
std::vector<Vec3> sharePixels(const RenderedImage& image, TileShare share);
void placeSharePixels(RenderedImage& image, TileShare share, std::span<const Vec3> pixels);

// The display image: exposure, a soft shoulder for highlights, the sRGB curve.
Image toDisplay(const RenderedImage& image);

// The k of the caustic density estimate.
constexpr int kCausticNeighbors = 64;

}  // namespace facetlight
