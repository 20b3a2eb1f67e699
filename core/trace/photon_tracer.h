#pragma once
// The photon tracer: photons from a light model into a stone, through Fresnel reflections and refractions,
// out through its facets, counted in FacetStats. Photon i draws its random numbers from Rng(seed, i) only
// and the tallies are integers, so a trace gives the same bits for any thread count, and a distributed run
// that splits the blocks among ranks and merges their tallies reproduces a local one exactly.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "geometry/ray.h"
#include "optics/fresnel.h"
#include "optics/light_model.h"
#include "optics/material.h"
#include "stats/facet_stats.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"

namespace facetlight {

class ConvexBeamEntry;
class ConvexIntersector;
class EmbreeIntersector;

// Shared with whoever runs a trace: progress to read and a cancel flag to set, both while it runs.
struct TraceControl {
    std::atomic<uint64_t> photonsDone{0};
    std::atomic<bool> cancel{false};  // checked before each block; a cancelled trace returns cancelled = true
};

// Everything a photon needs, prepared once per trace: the stone's intersector, the light, the material.
class TraceScene {
  public:
    // Throws Error for settings that cannot be traced on this stone (e.g. intersector "convex" on a
    // non-convex stone). The stone must outlive the scene.
    TraceScene(const Stone& stone, const TraceSettings& settings);
    ~TraceScene();

    const Stone& stone() const { return stone_; }
    const TraceSettings& settings() const { return settings_; }
    bool usesEmbree() const { return embree_ != nullptr; }

  private:
    friend class PhotonWalker;
    // Dispersion gives each photon its own wavelength and index.
    bool perPhotonIndex() const { return settings_.dispersion && material_.dispersive(); }
    const Stone& stone_;
    TraceSettings settings_;
    Material material_;
    LightModel light_;
    float fixedIndex_;  // the index at 589.3 nm, used when dispersion is off
    std::vector<Region> facetRegion_;
    std::vector<Vec3f> normal_;
    Vec3f up_;             // the viewer's vertical in the stone's frame (tilt undone)
    float cosHeadShadow_;  // exits closer to vertical than this are hidden by the head (2: no cone)
    std::array<float, kConeCount> cosCone_;
    ExitAngleBins exitBin_;
    std::unique_ptr<ConvexIntersector> convex_;
    std::unique_ptr<EmbreeIntersector> embree_;
    // Collimated light on a convex stone: the entry search with its divisions done once.
    std::unique_ptr<ConvexBeamEntry> beam_;
    // Collimated light at one index of refraction: every photon entering through facet f meets it at the
    // same angle, so its Fresnel reflectance and both directions are worked out once per facet.
    struct FixedEntry {
        float reflectance;
        Vec3f reflected, refracted;
    };
    std::vector<FixedEntry> fixedEntry_;
};

// One photon's fate, for the renderer and photon maps that reuse the tracer.
enum class PhotonOutcome : uint8_t { Missed, ReflectedAtEntry, Exited, Trapped };
struct PhotonPath {
    PhotonOutcome outcome = PhotonOutcome::Missed;
    float wavelengthNm = 0;
    uint32_t entryFacet = 0;  // valid unless Missed
    uint32_t exitFacet = 0;   // valid when Exited (the facet of reflection when ReflectedAtEntry)
    uint32_t bounces = 0;     // internal reflections
    Vec3f exitPosition;       // where it left the surface (Exited or ReflectedAtEntry)
    Vec3f exitDirection;      // unit, outside the stone
};

// Traces photon `index` of the job exactly as a full trace would.
void tracePhoton(const TraceScene& scene, uint64_t index, PhotonPath& out);

// Photons are handed out in blocks of this many consecutive indices.
constexpr uint64_t kPhotonBlock = 4096;
inline uint64_t blockCount(uint64_t photons) {
    return (photons + kPhotonBlock - 1) / kPhotonBlock;
}

// Traces blocks [firstBlock, lastBlock) of the job (clipped to settings.photons) with `threads` workers and
// adds their tallies to `stats` (sized for the stone's facets). Returns false when cancelled before all
// blocks were traced. A distributed run gives each rank a block range and sums the tallies with
// FacetStats::merge.
bool traceBlocks(const TraceScene& scene, uint64_t firstBlock, uint64_t lastBlock, int threads,
                 FacetStats& stats, TraceControl* control = nullptr);

struct TraceResult {
    FacetStats stats;
    TraceTiming timing;
    // True when cancelled through TraceControl: `stats` then holds the blocks finished so far, which depend
    // on timing and are not reproducible.
    bool cancelled = false;
};

// The whole job: settings.photons photons with settings.threads workers.
TraceResult trace(const Stone& stone, const TraceSettings& settings, TraceControl* control = nullptr);

}  // namespace facetlight
