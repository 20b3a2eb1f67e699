#pragma once
// What a job will cost before it runs (docs/reliability.md, "How long a job may take"): its parts (the trace,
// the viewer, the photon map, the render, the fire picture, the ASET view, the tilt series; a sweep's grid
// and its search's finer rounds) in seconds on this machine, from the rates cost_calibration.h measures once.
#include <cstdint>
#include <string>
#include <vector>

#include "study/study.h"

namespace facetlight {

// Seconds of one thread per unit of each kind of work, measured on the reference stone (calibrateCostRates).
struct CostRates {
    double tracePhoton = 0;      // a photon of the statistics' trace (and of a sweep's point)
    double fireTracePhoton = 0;  // the same with the fire trace (fire.enabled: C, D and F as well)
    double viewerUnit = 0;       // a view ray or lamp photon of the viewer (viewerUnits)
    double mapPhoton = 0;   // a photon of a map of kCalibrationMapPhotons, its share of the build included
    double renderRay = 0;   // a render's pixel x sample x bounce of its depth (max_depth)
    double fireRay = 0;     // a fire picture's pixel x wavelength x bounce of the render's depth
    double asetRay = 0;     // a view ray of the ASET view and of each tilt frame (pixel x aset sample)
    double framePixel = 0;  // a tilt frame's pixel drawn and encoded into tilt.webp (one thread)
    // A job's fixed work, whatever its size (one thread): the statistics, heatmaps, cutting sheet, diagram
    // and plots of a study with a small render; a sweep's pictures and best design alike.
    double jobFiles = 0;
};

// The map photons the calibration traces and builds a map of. A larger map costs more a photon: its tree's
// build grows as n log n, so the estimate scales the rate by log n / log kCalibrationMapPhotons.
constexpr uint64_t kCalibrationMapPhotons = 20'000;

// The estimate is the rates' time times this. The rates are one thread's on the reference stone in its
// default light; a job's threads seldom scale perfectly (1.7-1.96 x on 2 threads, docs/performance.md),
// stones with more facets or that keep light inside longer trace slower, and the machine may be shared.
constexpr double kCostSafetyFactor = 2;

// A part of a job's work: its name as the detail says it ("render"), the field that makes it most costly
// against its default ("render.samples"), its size in words ("2048x2048 pixels x 256 samples x depth 64")
// and its estimated seconds.
struct CostPart {
    std::string name, field, size;
    double seconds = 0;
};

struct JobCost {
    std::vector<CostPart> parts;  // the ones the job has, in the order they run
    double seconds = 0;           // all of them
    // The costliest part (the trace: every job has one).
    const CostPart& largest() const;
};

// The job's parts with `threads` workers (what it will get: its threads capped at the machine's cores), each
// rate's time divided among them and multiplied by kCostSafetyFactor. A sweep's points are the product of
// its axes' sizes; with `maximize`, each finer round has at most 2 x refineSteps + 1 values along each axis
// of more than one value (sweep/optimizer.h) and photonGrowth times the photons of the round before.
JobCost estimateJobCost(const StudySettings& settings, const CostRates& rates, int threads);

}  // namespace facetlight
