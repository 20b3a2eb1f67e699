#pragma once
// The photon tracer: photons from a light model into a stone, through Fresnel reflections and refractions,
// out through its facets, counted in FacetStats. Photon i draws its random numbers from Rng(seed, i) only
// and the tallies are integers, so a trace gives the same bits for any thread count, and a distributed run
// that splits the blocks among ranks and merges their tallies reproduces a local one exactly.
#include <cstdint>
#include <optional>

#include <nlohmann/json.hpp>

#include "geometry/ray.h"
#include "io/cutting_sheet.h"
#include "stone/stone_size.h"
#include "stats/facet_stats.h"
#include "stats/fire_stats.h"
#include "trace/trace_base.h"
#include "util/run_control.h"

namespace facetlight {

// One photon's fate, for the renderer and photon maps that reuse the tracer.
enum class PhotonOutcome : uint8_t { Missed, ReflectedAtEntry, Exited, Trapped, Absorbed };
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
void tracePhoton(const TraceBase& trace, uint64_t index, PhotonPath& out);

// Photons are handed out in blocks of this many consecutive indices.
constexpr uint64_t kPhotonBlock = 4096;
inline uint64_t blockCount(uint64_t photons) {
    return (photons + kPhotonBlock - 1) / kPhotonBlock;
}

// Traces blocks [firstBlock, lastBlock) of the job (clipped to settings.photons) with `threads` workers and
// adds their tallies to `stats` (sized for the stone's facets), and with `fire` the fire trace's tallies of
// the same photons to *fire (trace/fire_trace.h), advancing control->done() by the photons traced. Returns
// false when cancelled before all blocks were traced. A distributed run gives each rank a block range and
// sums the tallies with FacetStats::merge.
bool traceBlocks(const TraceBase& trace, uint64_t firstBlock, uint64_t lastBlock, int threads,
                 FacetStats& stats, RunControl* control = nullptr, FireStats* fire = nullptr);

struct TraceResult {
    FacetStats stats;
    TraceTiming timing;
    // True when cancelled through RunControl: `stats` then holds the blocks finished so far, which depend on
    // timing and are not reproducible.
    bool cancelled = false;
    std::optional<FireStats> fire;  // when settings.fire.enabled
};

// The facet statistics of a trace with the job's settings, and the fire trace's `fire` member when it ran
// (docs/stats-schema.md): what every trace reports, a sweep's points included.
nlohmann::json traceReport(const TraceResult& result, const Stone& stone, const TraceSettings& settings);

// What stats.json says of the stone beside its statistics (docs/gemcad.md): the material traced and where it
// came from, the cutting sheet (none for a mesh that is not convex) and the size and weight at size_mm (none
// without a girdle width to scale by). Worked out once by those that write stats.json, not for sweep points.
struct DesignFacts {
    MaterialChoice material;
    std::string doubleRefraction;  // how a doubly refracting material was traced; empty for one index
    std::optional<CuttingSheet> sheet;
    std::optional<StoneSize> size;
};
DesignFacts designFacts(const Stone& stone, const TraceSettings& settings);
// Adds `material`, `cutting_sheet` and `size` to a trace's statistics.
void addDesignFacts(nlohmann::json& stats, const DesignFacts& facts);

// The whole job: the trace's settings.photons photons with settings.threads workers (and the fire trace when
// settings.fire.enabled).
TraceResult trace(const TraceBase& trace, RunControl* control = nullptr);

}  // namespace facetlight
