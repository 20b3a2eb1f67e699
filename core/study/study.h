#pragma once
// A study is what a job asks for: trace photons through a stone for the statistics, then (optionally) build
// the photon maps and render the pictures. The CLI's `render` and the service's job worker both run one.
#include <cstdint>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "render/render_settings.h"
#include "render/view_settings.h"
#include "stone/stone.h"
#include "study/result_files.h"
#include "sweep/sweep_job.h"
#include "trace/trace_settings.h"
#include "util/distributed.h"
#include "util/run_control.h"
#include "viewer/colour_view.h"
#include "viewer/doubling.h"
#include "viewer/polariscope.h"

namespace facetlight {

struct StudySettings {
    TraceSettings trace;
    std::optional<RenderSettings> render;  // none: statistics only
    // The ASET view through the render's camera at its size (needs a render): aset.png and stats "aset".
    std::optional<AsetSettings> aset;
    // The stone rocked through a tilt series of ASET views (needs a render; the ASET settings or their
    // defaults): tilt.webp, tilt.png and stats "tilt_series".
    std::optional<TiltSeriesSettings> tiltSeries;
    // The stone through the render's camera under a small bright light in true spectral colour (needs a
    // render): fire.png.
    std::optional<FirePictureSettings> firePicture;
    // The stone turned between crossed polarisers (docs/optics.md, "The polariscope"): polariscope.png,
    // polariscope.webp and stats "polariscope".
    std::optional<PolariscopeSettings> polariscope;
    // The stone face-up through a loupe, its pavilion's edges doubled by a doubly refracting stone
    // (docs/optics.md, "The doubling"): doubling.png and stats "doubling".
    std::optional<DoublingSettings> doubling;
    // The stone face-up in true colour under a dome of a CIE illuminant, absorbing along every path inside
    // (docs/optics.md, "The colour a viewer sees"): colour.png and stats "colour"; in a sweep, every point's
    // colour figures.
    std::optional<ColourSettings> colour;
    // A sweep of the job's shape (docs/sweeps.md) instead of one trace: runSweepJob, not runStudy.
    std::optional<SweepRequest> sweep;
};

// Builds one Scene for every phase and runs them, each reporting to `control` (RunPhase::Tracing, Viewing,
// PhotonMap, Rendering, then Done; done() and total() in photons, view rays or pixels). Throws Canceled when
// control.cancel() is called while it runs, Error on bad settings.
StudyResult runStudy(const Stone& stone, const StudySettings& settings, RunControl& control);
// The same on every rank of `comm` (docs/distributed.md): the trace, the map photons and the render's tiles
// are split across the ranks and rank 0's result equals the single-process one apart from `timing`; the other
// ranks return empty results. control.done() and total() count this rank's share of each phase.
StudyResult runStudy(const Stone& stone, const StudySettings& settings, RunControl& control,
                     Communicator& comm);
// A sweep job (settings.sweep) of `shape`, a shape of the cut library or a design or mesh file's path
// (planSweepOf), on every rank of `comm`: rank 0's result holds its files (sweep.json, sweep.csv, sweep.png of
// the first figure; with a search best.json, best.obj and best.asc).
StudyResult runSweepJob(const std::string& shape, const StudySettings& settings, RunControl& control,
                        Communicator& comm, const SweepCheckpoint& checkpoint = {});
// The units of a phase of the whole study, over every rank: its photons or pixels (0 for the others).
uint64_t studyUnits(const StudySettings& settings, RunPhase phase);

}  // namespace facetlight
