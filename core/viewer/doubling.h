#pragma once
// The doubling (docs/optics.md, "The doubling"): a doubly refracting stone seen face-up through a loupe shows
// its pavilion's edges twice, once through each of the two waves the crown splits every ray into; the classic
// test that tells moissanite from diamond. Measured on view rays run backwards from the eye: each pixel's ray
// enters the crown and goes on both as the ordinary and as the extraordinary wave to the pavilion, and the
// distance between the two images of one pavilion point follows from where the two waves meet it.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "settings/settings_schema.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/run_control.h"

namespace facetlight {

// A job's `doubling` (JSON, described once in doublingSettingsSchema()).
struct DoublingSettings {
    int pictureSize = 400;  // view rays across the face-up view, one pair a pixel (the picture's pixels)
    double tiltDeg = 0;     // the stone tilted about its x axis, as light.tilt_deg tilts it
    double loupe = 10;      // the loupe's magnification the angular figure assumes (10x: as if from 25 mm)
};

const settings::Schema<DoublingSettings>& doublingSettingsSchema();

// The distance between the two images over a set of pixels, in mm at the stone's size.
struct DoublingSpread {
    uint64_t pixels = 0;                         // pixels where both waves reach the same pavilion facet
    double medianMm = 0, lowMm = 0, highMm = 0;  // median and quartiles
};

struct Doubling {
    bool doublyRefracting = false;  // traced as two waves (a uniaxial or biaxial material); else one image
    std::string tracedAs;           // how, in words
    double nO = 0, nE = 0;          // at 589.3 nm; nE == nO for one image; a biaxial stone's beta and gamma
    double nA = 0;                  // a biaxial stone's alpha at 589.3 nm; else 0
    double viewToAxisDeg = 0;       // the angle between the line of sight and the (nearer) optic axis
    double sizeMm = 0, diameterMm = 0, loupe = 10, tiltDeg = 0;
    DoublingSpread table;  // seen through the table
    DoublingSpread crown;  // seen through any crown facet, the table included

    // The face-up picture's pixels, row 0 at the top (+y seen from above), `size` across a square of
    // 2 halfWidthMm: the crown facet each pixel's ray enters (-1: it misses the stone), the pavilion facet
    // its ordinary and its extraordinary wave reach first (-1: none, e.g. the girdle), and the distance
    // between the two images there in mm (negative where not measured).
    int size = 0;
    double halfWidthMm = 0;
    std::vector<int32_t> entry, ordinary, extraordinary;
    std::vector<float> doublingMm;

    double shareOfDiameter(double mm) const { return diameterMm > 0 ? mm / diameterMm : 0; }
    // The angle the distance subtends seen through the loupe: from 250 mm (the near point) divided by it.
    double arcMinutes(double mm) const;
};

// `settings` gives the stone's material, optic axis and size; the view is orthographic (a loupe focused on
// the stone from afar) along -z of the stone tilted by `d.tiltDeg`, each pixel's ray through its centre: no
// random draws, the same numbers at any thread count. The waves come from the interface optics of the
// tracer (optics/birefringence.h) at 589.3 nm; within TraceBase::nearOpticAxis of a uniaxial stone's axis
// they coincide; a biaxial stone splits into its fast and slow waves. An isotropic material gives one image
// and zero doubling. Adds each pixel to control->done() (the caller starts the phase).
Doubling doubling(const Stone& stone, const TraceSettings& settings, const DoublingSettings& d,
                  RunControl* control = nullptr);

nlohmann::json toJson(const Doubling& d);

}  // namespace facetlight
