#pragma once
// The fire trace: each photon of the job followed at the Fraunhofer C, D and F lines with the same random
// choices, and its red and blue exits through table or crown toward the viewer compared: the angle between
// them, whether it exceeds what the viewer's pupil spans, where they left (docs/physics.md, "Fire"). The
// tallies are integers, so a fire trace gives the same bits for any thread or rank count.
#include <array>
#include <cstdint>

#include "stats/facet_stats.h"
#include "stats/fire_stats.h"
#include "trace/trace_base.h"

namespace facetlight {

// One band of the fire trace: its wavelength (kFireWavelengthsNm, or 589.3 nm when the scene is not
// dispersive) and the index of refraction there.
struct FireBand {
    float index;
    float wavelengthNm;
};
std::array<FireBand, kFireBands> fireBands(const Scene& scene);

// Adds photons [begin, end) of the job to the plain trace's tally `plain` and to `stats` (sized for the
// stone's facets). A convex stone's bands are walked a packet at a time, one (photon, band) per SIMD lane,
// a collimated beam's photons started once for the plain walk and the bands.
void traceFire(const TraceBase& trace, uint64_t begin, uint64_t end, FacetStats& plain, FireStats& stats);
// The same with each photon's bands walked one at a time: the reference traceFire is tested against.
void traceFirePhotonByPhoton(const TraceBase& trace, uint64_t begin, uint64_t end, FireStats& stats);

}  // namespace facetlight
