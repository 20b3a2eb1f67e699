#include "render/renderer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "colour/colour_space.h"
#include "optics/spectrum.h"
#include "render/detail/sample_tracer.h"
#include "util/error.h"
#include "util/parallel.h"
#include "util/random.h"

namespace facetlight {
namespace {

constexpr int kTile = 16;

// Everything a worker reads: shared, constant.
struct Context {
    const Scene& scene;
    const PhotonMap& caustics;
    const RenderSettings& settings;
    SpectralBands bands;
    Vec3 toViewer;  // world
    GatherSettings gather;
    double causticScale;  // 1 / samples: each sample adds its share of the (already coloured) caustic light
};

// Per worker, never shared.
struct Worker {
    GatherState gatherState;
    std::array<Neighbor, kCausticNeighbors> neighbors;
};

// The studio around the stone: the floor, lit by the direct light and the caustic photon map, and the
// studio environment above it.
class Studio {
  public:
    Studio(const Context& c, Worker& w) : c_(c), w_(w) {}

    bool stoneFirst(const Vec3& origin, const Vec3& dir, double t) const {
        double tFloor = INFINITY;
        return !c_.scene.hitFloor(origin, dir, tFloor) || t < tFloor;
    }

    Vec3 radiance(const Vec3& origin, const Vec3& dir, const Vec3& colour, double weight, Rng& rng) {
        double tFloor = INFINITY;
        if (c_.scene.hitFloor(origin, dir, tFloor))
            return floorRadiance(origin + dir * tFloor, colour, rng) * weight;
        return colour * (weight * Scene::environment(c_.scene.toWorld(dir), c_.toViewer));
    }

  private:
    Vec3 floorRadiance(const Vec3& p, const Vec3& colour, Rng& rng) {
        Vec3 irradiance = colour * c_.scene.directIrradiance(p, rng);
        if (!c_.caustics.empty()) {
            irradiance +=
                c_.caustics.estimate<Vec3>(p, w_.neighbors, w_.gatherState, c_.gather,
                                           [](const Photon& ph) {
                                               return ph.wavelength() > 0
                                                          ? photonColour(ph.wavelength()) * double(ph.power)
                                                          : Vec3{1, 1, 1} * double(ph.power);
                                           }) *
                c_.causticScale;
        }
        // Lambertian: radiance albedo E / pi; the display's exposure takes the 1 / pi (an open floor under
        // unit irradiance shows as albedo).
        return irradiance * Scene::kFloorAlbedo;
    }

    const Context& c_;
    Worker& w_;
};

struct TileRect {
    int x0, y0, x1, y1;
};

int tileCount(int width, int height) {
    return ((width + kTile - 1) / kTile) * ((height + kTile - 1) / kTile);
}

// Tiles of the share: offset, offset + stride, ...
int shareTileCount(int tiles, TileShare share) {
    return tiles > share.offset ? (tiles - share.offset + share.stride - 1) / share.stride : 0;
}

TileRect tileRect(int tile, int width, int height) {
    const int tilesX = (width + kTile - 1) / kTile;
    const int x0 = (tile % tilesX) * kTile, y0 = (tile / tilesX) * kTile;
    return {x0, y0, std::min(x0 + kTile, width), std::min(y0 + kTile, height)};
}

void checkShare(TileShare share) {
    if (share.stride < 1 || share.offset < 0 || share.offset >= share.stride)
        throw Error("tile share " + std::to_string(share.offset) + " of " + std::to_string(share.stride) +
                    " is not a valid share");
}

// Calls f(index) for every pixel of the share, tile by tile in tile order, row by row within a tile.
template <class F>
void forEachSharePixel(int width, int height, TileShare share, F&& f) {
    const int tiles = tileCount(width, height);
    for (int tile = share.offset; tile < tiles; tile += share.stride) {
        const TileRect t = tileRect(tile, width, height);
        for (int y = t.y0; y < t.y1; ++y) {
            for (int x = t.x0; x < t.x1; ++x) f(size_t(y) * size_t(width) + size_t(x));
        }
    }
}

}  // namespace

uint64_t sharePixelCount(int width, int height, TileShare share) {
    checkShare(share);
    uint64_t n = 0;
    forEachSharePixel(width, height, share, [&](size_t) { ++n; });
    return n;
}

std::vector<Vec3> sharePixels(const RenderedImage& image, TileShare share) {
    std::vector<Vec3> out;
    out.reserve(sharePixelCount(image.width, image.height, share));
    forEachSharePixel(image.width, image.height, share, [&](size_t i) { out.push_back(image.pixels[i]); });
    return out;
}

void placeSharePixels(RenderedImage& image, TileShare share, std::span<const Vec3> pixels) {
    if (pixels.size() != sharePixelCount(image.width, image.height, share))
        throw Error("a rank sent " + std::to_string(pixels.size()) + " pixels for its tiles, not " +
                    std::to_string(sharePixelCount(image.width, image.height, share)));
    size_t next = 0;
    forEachSharePixel(image.width, image.height, share, [&](size_t i) { image.pixels[i] = pixels[next++]; });
}

RenderedImage render(const Scene& scene, const PhotonMap& caustics, const RenderSettings& settings,
                     int threads, uint64_t seed, RunControl* control, TileShare share) {
    checkShare(share);
    const Vec3 target = scene.toWorld(scene.center());
    const Camera camera(settings.camera, target, scene.diameter(), settings.width, settings.height);
    GatherSettings gather;
    gather.maxRadius = float(0.04 * scene.diameter());
    gather.coneK = 1.1f;
    const Context context{scene,
                          caustics,
                          settings,
                          SpectralBands(settings.samples),
                          normalize(camera.position() - target),
                          gather,
                          1.0 / settings.samples};

    RenderedImage image;
    image.width = settings.width;
    image.height = settings.height;
    image.pixels.assign(size_t(settings.width) * size_t(settings.height), Vec3{});
    const int tiles = shareTileCount(tileCount(settings.width, settings.height), share);
    const Vec3 eye = scene.toStone(camera.position());
    const double fixedIndex = scene.refractiveIndex(Material::kSodiumD);
    const Vec3 white = Vec3{1, 1, 1} * context.causticScale;

    const WorkerStates<Worker> workers = parallelForBlocks(
        BlockLoop{0, uint64_t(tiles), 1, threads}, control, Worker{},
        [&](Worker& worker, uint64_t k, uint64_t) {
            const auto [x0, y0, x1, y1] =
                tileRect(share.offset + int(k) * share.stride, settings.width, settings.height);
            for (int y = y0; y < y1; ++y) {
                for (int x = x0; x < x1; ++x) {
                    const uint64_t index = uint64_t(y) * uint64_t(settings.width) + uint64_t(x);
                    Rng rng(mix64(seed ^ 0x52454e444552ULL), index);
                    Studio studio(context, worker);
                    detail::SampleTracer tracer(scene, settings.maxDepth, studio, rng);
                    Vec3 sum;
                    for (int s = 0; s < settings.samples; ++s) {
                        const double px = x + rng.uniformDouble(), py = y + rng.uniformDouble();
                        // Sample s takes band s, at a wavelength jittered within it when that changes the
                        // index.
                        const double u = rng.uniformDouble();
                        const double n = scene.dispersive()
                                             ? scene.refractiveIndex(context.bands.wavelength(s, u))
                                             : fixedIndex;
                        const Vec3 dir = scene.toStone(camera.direction(px, py));
                        sum += tracer.trace(eye, dir, n, context.bands.colour(s), white);
                    }
                    image.pixels[index] = sum;
                }
            }
            return uint64_t(x1 - x0) * uint64_t(y1 - y0);
        });
    image.cancelled = !workers.finished;
    return image;
}

RenderedImage render(Communicator& comm, const Scene& scene, const PhotonMap& caustics,
                     const RenderSettings& settings, int threads, uint64_t seed, RunControl* control) {
    const TileShare mine{comm.rank(), comm.size()};
    RenderedImage image = render(scene, caustics, settings, threads, seed, control, mine);
    image.cancelled = anyRank(comm, image.cancelled);
    if (comm.size() == 1 || image.cancelled) return image;
    // Rank 0's own tiles are in place already.
    const std::vector<Vec3> pixels = comm.isRoot() ? std::vector<Vec3>{} : sharePixels(image, mine);
    const std::vector<std::string> parts = comm.gather(asBytes(std::span<const Vec3>(pixels)));
    for (int r = 1; r < int(parts.size()); ++r) {
        std::vector<Vec3> theirs;
        appendFromBytes(parts[r], theirs);
        placeSharePixels(image, {r, comm.size()}, theirs);
    }
    return image;
}

Image toDisplay(const RenderedImage& r) {
    Image image(r.width, r.height);
    auto tone = [](double v) {
        constexpr double knee = 0.8;  // linear below, then an exponential shoulder toward 1
        v = std::max(v, 0.0);
        return float(
            srgbEncode(v <= knee ? v : knee + (1 - knee) * (1 - std::exp(-(v - knee) / (1 - knee)))));
    };
    for (int y = 0; y < r.height; ++y) {
        for (int x = 0; x < r.width; ++x) {
            const Vec3& p = r.pixels[size_t(y) * r.width + x];
            image.at(x, y) = {tone(p.x), tone(p.y), tone(p.z)};
        }
    }
    return image;
}

}  // namespace facetlight
