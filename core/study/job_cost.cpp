#include "study/job_cost.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <span>

#include "optics/material.h"
#include "scene/scene.h"
#include "sweep/optimizer.h"
#include "util/number_text.h"
#include "viewer/viewer_figures.h"

namespace facetlight {
namespace {

// A setting that multiplies a part's work, against its default: the part names the one furthest above its
// default, the first to lower.
struct Factor {
    const char* field;
    double value, usual;
};

std::string costliest(std::initializer_list<Factor> factors) {
    const Factor* top = factors.begin();
    for (const Factor& f : factors)
        if (f.value / f.usual > top->value / top->usual) top = &f;
    return top->field;
}

std::string count(double n) {
    return n < 1e6 ? formatNumber("%.0f", n) : formatNumber("%.3g", n);
}

// How much more a map photon costs in a map of `n` than in the calibration's (job_cost.h).
double mapGrowth(uint64_t n) {
    return std::log2(double(std::max(n, kCalibrationMapPhotons))) / std::log2(double(kCalibrationMapPhotons));
}

std::string pixels(const RenderSettings& r) {
    return std::to_string(r.width) + "x" + std::to_string(r.height) + " pixels";
}

// How much longer a doubly refracting stone traced polarised takes, its rays split into two waves at every
// facet: `uniaxial` or `biaxial` times a singly refracting one's time.
double splitFactor(const TraceSettings& t, double uniaxial, double biaxial) {
    if (t.polarization == PolarizationMode::Off) return 1;
    switch (chosenOptic(t)) {
        case Optic::Isotropic:
            return 1;
        case Optic::Uniaxial:
            return uniaxial;
        case Optic::Biaxial:
            return biaxial;
    }
    return 1;
}

// The calibration traces polarised, the default (cost_calibration.cpp); an unpolarised one takes about as
// long (0.91-0.97x its time quiet, docs/performance.md, "Polarised and birefringent tracing"). A doubly
// refracting stone splits the light at every facet: a uniaxial one 2.0-4.4x (SCALAR to AVX-512, whose
// unpolarised packet walk gains most; bench_trace's PolarizedVsPlain with the crystal interface in lanes,
// 2026-12-03 17:56; 5.1x at 17:20), counted at 5. A biaxial one finds its waves from a quartic's roots, lane
// by lane: 20x (`facetlight trace --mesh round_brilliant --photons 2000000 --threads 1 --no-view --material
// topaz`, user time, 3 runs each, 2026-12-03 19:12, AVX-512: 4.60-4.68 s, `--polarization off` 0.23-0.24 s;
// 25x at 17:33 before the interface's common case was cut, docs/performance.md, "Biaxial crystal interface"),
// counted at 20.
double polarizationFactor(const TraceSettings& t) {
    return splitFactor(t, 5, 20);
}

// The viewer's and the colour view's rays split likewise, one at a time either way, so they lose no SIMD
// lanes to the split. The rates are polarised diamond's (the calibration's stone, whose index makes its rays
// bounce more than a lower stone's), so the factor is a stone's time over diamond's: the viewer at its
// default settings (`facetlight trace --mesh round_brilliant --photons 1000 --threads 1 --material M`, user
// time, 3 runs, 2026-12-03 19:19) diamond 1.58-1.69 s, sapphire 2.55-2.67 s (1.6x), topaz 5.18-5.28 s (3.3x);
// its office view alone (`--office-points 10000 --spot-photons 1000`) 1.8x and 3.6x, its spot lamps alone
// (`--office-points 100 --spot-photons 300000`) 1.5x and 2.9x; the colour view (`--no-view --colour
// --colour-picture 200`) diamond 0.88-0.90 s, ruby 1.81-1.88 s (2.1x), zoisite 4.36-4.37 s (4.9x): counted at
// 2.5 and 5. (Against the same stone unpolarised the split costs more, 3.1-3.2x and 6.6-7.9x, but a lower
// stone's unpolarised rays are cheaper than diamond's: 4 and 8 overstated a birefringent job's viewer about
// 2.4 times.)
double viewRayFactor(const TraceSettings& t) {
    return splitFactor(t, 2.5, 5);
}

// A trace of `photons` photons (with the fire trace when enabled): every job's, and each sweep point's.
double traceSeconds(const TraceSettings& t, uint64_t photons, const CostRates& rates) {
    return double(photons) * (t.fire.enabled ? rates.fireTracePhoton : rates.tracePhoton) * polarizationFactor(t);
}

double viewerSeconds(const TraceSettings& t, const CostRates& rates) {
    return t.viewer.enabled ? double(viewerUnits(t.viewer)) * rates.viewerUnit * viewRayFactor(t) : 0;
}

std::string viewerField(const ViewerSettings& v) {
    const ViewerSettings usual;
    return costliest({{"viewer.office.points", double(v.office.points), double(usual.office.points)},
                      {"viewer.spot.photons", double(v.spot.photons), double(usual.spot.photons)},
                      {"viewer.tilts", double(v.tilts), double(usual.tilts)},
                      {"viewer.azimuths", double(v.azimuths), double(usual.azimuths)}});
}

// A sweep's points: its grid's, and the most each of its search's finer rounds traces.
struct SweepGridSize {
    double points = 1, refined = 1;
};
SweepGridSize sweepGridSize(const SweepRequest& sweep) {
    SweepGridSize n;
    const OptimizeSettings search;
    for (const SweepAxis& axis : sweep.axes) {
        n.points *= double(axis.size());
        n.refined *= axis.size() > 1 ? 2 * search.refineSteps + 1 : 1;
    }
    return n;
}

// The face-up colour views a study makes: one, or one a point of a sweep and of its search's rounds.
double colourViews(const StudySettings& s) {
    if (!s.sweep) return 1;
    const SweepGridSize n = sweepGridSize(*s.sweep);
    return n.points + (s.sweep->maximize.empty() ? 0 : s.sweep->refineRounds * n.refined);
}

// f(trace) of a sweep's point, averaged over its material axis's choices (a point's cost depends on how its
// material splits the light), or f(t) without one.
template <class F>
double meanOverMaterials(const TraceSettings& t, const SweepRequest* sweep, F f) {
    const auto axes = sweep ? std::span<const SweepAxis>(sweep->axes) : std::span<const SweepAxis>();
    const auto material =
        std::find_if(axes.begin(), axes.end(), [](const SweepAxis& a) { return a.name == "material"; });
    if (material == axes.end()) return f(t);
    double sum = 0;
    for (const std::string& name : material->choices) {
        TraceSettings point = t;
        point.material = name;
        sum += f(point);
    }
    return sum / double(material->choices.size());
}

// A sweep's grid, and with `maximize` its search's finer rounds (sweep/optimizer.h's maximize()).
void addSweepParts(const TraceSettings& t, const SweepRequest& sweep, const CostRates& rates,
                   std::vector<CostPart>& parts) {
    const TraceSettings usual;
    const OptimizeSettings search;
    const auto [points, refined] = sweepGridSize(sweep);
    const double point = meanOverMaterials(t, &sweep, [&](const TraceSettings& p) {
        return traceSeconds(p, p.photons, rates) + viewerSeconds(p, rates);
    });
    // The reference stone the viewer figures are scored against is traced once.
    parts.push_back(
        {"sweep",
         costliest({{"photons", double(t.photons), double(usual.photons)}, {"sweep.axes", points, 1}}),
         count(points) + " points x " + count(double(t.photons)) + " photons",
         points * point + viewerSeconds(t, rates)});
    if (sweep.maximize.empty() || sweep.refineRounds == 0) return;
    double seconds = 0, growth = 1;
    uint64_t photons = t.photons;
    for (int round = 0; round < sweep.refineRounds; ++round) {
        photons = std::min<uint64_t>(photons * search.photonGrowth, kMaxPhotons);
        growth *= double(search.photonGrowth);
        // The viewer's samples grow with the photons; each round scores against its own reference.
        const TraceSettings r = searchRoundTrace(t, photons);
        seconds += meanOverMaterials(r, &sweep, [&](const TraceSettings& p) {
            return refined * (traceSeconds(p, photons, rates) + viewerSeconds(p, rates)) +
                   viewerSeconds(p, rates);
        });
    }
    const double usualGrowth = std::pow(double(search.photonGrowth), SweepRequest{}.refineRounds);
    parts.push_back({"search",
                     costliest({{"photons", double(t.photons), double(usual.photons)},
                                {"sweep.refine_rounds", growth, usualGrowth}}),
                     std::to_string(sweep.refineRounds) + " finer rounds of up to " + count(refined) +
                         " points, the last at " + count(double(photons)) + " photons",
                     seconds});
}

}  // namespace

const CostPart& JobCost::largest() const {
    return *std::max_element(parts.begin(), parts.end(),
                             [](const CostPart& a, const CostPart& b) { return a.seconds < b.seconds; });
}

JobCost estimateJobCost(const StudySettings& s, const CostRates& rates, int workers) {
    const int threads = std::max(1, workers);
    const TraceSettings& t = s.trace;
    std::vector<CostPart> parts;
    if (s.sweep) {
        addSweepParts(t, *s.sweep, rates, parts);
    } else {
        parts.push_back(
            {"trace", "photons",
             count(double(t.photons)) + " photons" + (t.fire.enabled ? " with the fire trace" : ""),
             traceSeconds(t, t.photons, rates)});
        // The stone's and the reference's (study.cpp's studyUnits): the reference is kept once traced, but
        // counting it keeps the estimate on the safe side.
        if (t.viewer.enabled)
            parts.push_back({"viewer", viewerField(t.viewer),
                             count(2 * double(viewerUnits(t.viewer))) + " view rays and lamp photons",
                             2 * viewerSeconds(t, rates)});
    }
    if (s.polariscope) {
        // Every position a polarised trace of its photons from below, on the rates above.
        const PolariscopeSettings& p = *s.polariscope;
        const PolariscopeSettings usual;
        TraceSettings polarised = t;
        polarised.polarization = PolarizationMode::On;
        polarised.fire.enabled = false;
        parts.push_back({"polariscope",
                         costliest({{"polariscope.photons", double(p.photons), double(usual.photons)},
                                    {"polariscope.angles", double(p.angles), double(usual.angles)}}),
                         count(p.angles) + " positions x " + count(double(p.photons)) + " photons",
                         p.angles * traceSeconds(polarised, p.photons, rates)});
    }
    if (s.doubling) {
        // Each pixel three view rays (into the crown, then each wave to the pavilion), at the ASET view's rate.
        const double px = double(s.doubling->pictureSize) * double(s.doubling->pictureSize);
        parts.push_back({"doubling", "doubling.picture_size", count(px) + " pixels x 3 view rays",
                         3 * px * rates.asetRay});
    }
    if (s.colour) {
        // Each pixel `samples` paths, each a view ray at every one of `wavelengths`, at the ASET view's rate
        // (times the split's); in a sweep, at every point.
        const ColourSettings& c = *s.colour;
        const ColourSettings usual;
        const double views = colourViews(s);
        const double px = double(c.pictureSize) * double(c.pictureSize);
        parts.push_back(
            {"colour",
             costliest({{"colour.picture_size", px, double(usual.pictureSize) * usual.pictureSize},
                        {"colour.samples", double(c.samples), double(usual.samples)},
                        {"colour.wavelengths", double(c.wavelengths), double(usual.wavelengths)}}),
             (views > 1 ? count(views) + " views x " : "") + count(px) + " pixels x " +
                 std::to_string(c.samples) + " paths x " + std::to_string(c.wavelengths) + " wavelengths",
             views * px * c.samples * c.wavelengths * rates.asetRay *
                 meanOverMaterials(t, s.sweep ? &*s.sweep : nullptr, viewRayFactor)});
    }
    if (s.render) {
        const RenderSettings& r = *s.render;
        const RenderSettings usual;
        const double px = double(r.width) * double(r.height);
        const Factor width{"render.width", double(r.width), double(usual.width)};
        const Factor height{"render.height", double(r.height), double(usual.height)};
        const Factor depth{"render.max_depth", double(r.maxDepth), double(usual.maxDepth)};
        parts.push_back({"photon map", "render.map_photons", count(double(r.mapPhotons)) + " map photons",
                         double(r.mapPhotons) * rates.mapPhoton * mapGrowth(r.mapPhotons)});
        parts.push_back(
            {"render",
             costliest({{"render.samples", double(r.samples), double(usual.samples)}, width, height, depth}),
             pixels(r) + " x " + std::to_string(r.samples) + " samples x depth " + std::to_string(r.maxDepth),
             px * r.samples * r.maxDepth * rates.renderRay});
        if (s.firePicture) {
            const int n = s.firePicture->wavelengths;
            parts.push_back(
                {"fire picture",
                 costliest(
                     {{"fire_picture.wavelengths", double(n), double(FirePictureSettings{}.wavelengths)},
                      width,
                      height,
                      depth}),
                 pixels(r) + " x " + std::to_string(n) + " wavelengths x depth " + std::to_string(r.maxDepth),
                 px * n * r.maxDepth * rates.fireRay});
        }
        const AsetSettings aset = s.aset.value_or(AsetSettings{});
        const Factor samples{"aset.samples", double(aset.samples), double(AsetSettings{}.samples)};
        const std::string rays = pixels(r) + " x " + std::to_string(aset.samples) + " view rays";
        if (s.aset)
            parts.push_back(
                {"ASET view", costliest({samples, width, height}), rays, px * aset.samples * rates.asetRay});
        if (s.tiltSeries) {
            const TiltSeriesSettings& tilt = *s.tiltSeries;
            const TiltSeriesSettings usualTilt;
            const double frames = tilt.frameCount();
            // More frames come from a wider tilt or a finer step: the one further from its default.
            const Factor framesFactor = tilt.maxDeg / usualTilt.maxDeg > usualTilt.stepDeg / tilt.stepDeg
                                            ? Factor{"tilt_series.max_deg", frames, usualTilt.frameCount()}
                                            : Factor{"tilt_series.step_deg", frames, usualTilt.frameCount()};
            // Each frame's picture is drawn and encoded on one thread: not divided below.
            parts.push_back({"tilt series", costliest({framesFactor, samples, width, height}),
                             count(frames) + " frames x " + rays,
                             frames * px * (aset.samples * rates.asetRay + threads * rates.framePixel)});
        }
    }
    JobCost cost;
    for (CostPart& p : parts) {
        p.seconds *= kCostSafetyFactor / threads;
        cost.seconds += p.seconds;
    }
    // Drawn and written on one thread, after the parts above.
    parts.push_back({"files", "", "statistics, pictures and plots", rates.jobFiles * kCostSafetyFactor});
    cost.seconds += parts.back().seconds;
    cost.parts = std::move(parts);
    return cost;
}

}  // namespace facetlight
