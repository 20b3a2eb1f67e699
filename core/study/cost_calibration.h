#pragma once
// The rates a job's cost is estimated from (study/job_cost.h), measured on this machine: each kind of work a
// job does, run once at a small size on one thread.
#include "study/job_cost.h"

namespace facetlight {

// Runs a small study (its files), a short trace (plain and with fire), the viewer, a photon map, a render, a
// fire picture, an ASET view and a tilt series' frames of the reference round brilliant, each with fixed
// settings and seeds, and times them: about 0.4 s in all on a 2-core machine of 2026 (docs/reliability.md).
// Every rate is positive.
CostRates calibrateCostRates();

}  // namespace facetlight
