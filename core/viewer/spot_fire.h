#pragma once
// The spot set-up traced from the lamps (docs/physics.md, "Viewer figures"): photons from small distant lamps
// into the stone at every position of the motion, each followed at the Fraunhofer C, D and F lines with the
// same random choices (the fire trace's bands, trace/fire_trace.h), and their red and blue exits toward the
// viewer compared with what the pupil spans. Photon i draws from Rng(seed, i) alone and takes position
// i mod positions and lamp (i / positions) mod lamps; the tallies are integers: the same bits for any thread
// count.
#include <cstdint>
#include <vector>

#include "optics/viewer_settings.h"
#include "trace/trace_base.h"
#include "util/run_control.h"

namespace facetlight {

struct SpotTally {
    uint64_t photons = 0, hit = 0;  // drawn; met the stone
    // Of the hits: the D band out through table or crown within the viewing cone (light seen); red and blue
    // both so along one facet path (pairs), further apart than the pupil spans (coloured, the fire seen);
    // one of them so and the other not, or by another path (split).
    uint64_t seen = 0, pairs = 0, coloured = 0, split = 0;

    void merge(const SpotTally& o);
    bool operator==(const SpotTally&) const = default;
};

// The lamps the viewer does not hide, as world directions of travel (toward the stone). Throws Error naming
// "viewer.spot.lamps" when the viewer hides every one.
std::vector<Vec3> spotLamps(const ViewerSettings& settings);

// Traces settings.spot.photons photons of the trace's stone with its seed, threads and bounce limit; the
// scene's light plays no part (it must not be collimated: the photons' directions are the lamps'). Advances
// control->done() by the photons of each block. `finished`: whether it ran to the end.
SpotTally spotFire(const TraceBase& trace, const ViewerSettings& settings, RunControl* control,
                   bool& finished);

}  // namespace facetlight
