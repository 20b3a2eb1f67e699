#pragma once
// The colour a viewer sees (docs/optics.md, "The colour a viewer sees"): the stone face-up in true colour,
// each pixel's view rays traced back through the stone as the ASET view traces them (PhotonWalker::view),
// each at a set of wavelengths stratified over 380-780 nm with the same random draws (so that the
// wavelengths of a path part only where dispersion or the Fresnel odds make them), weighted by exp(-alpha L)
// along its path inside and by the light of the direction it leaves in: a uniform dome of the illuminant
// (D65, or A) less the viewer's head cone, over a ground that reflects `ground` of it. The spectrum each
// pixel receives, integrated against the CIE 1931 colour matching functions, gives XYZ, then sRGB and CIELAB.
#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "colour/cie.h"
#include "colour/colour_space.h"
#include "settings/settings_schema.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/run_control.h"

namespace facetlight {

// A job's `colour` (JSON, described once in colourSettingsSchema()).
struct ColourSettings {
    int pictureSize = 200;  // pixels across the face-up view
    int samples = 4;        // view paths per pixel
    int wavelengths = 16;   // each path traced at one wavelength in each of this many strata of 380-780 nm
    Illuminant illuminant = Illuminant::D65;
    double headConeDeg = 15;    // the viewer's head: no light from within this angle of the zenith
    double ground = 1;          // the ground's reflectance: 1 a white tray (the dome's own radiance), 0 black
    double extinctBelowL = 20;  // a pixel darker than this L* is extinct
    double saturatedAboveC = 40;  // a pixel of larger chroma C*ab is saturated
};

const settings::Schema<ColourSettings>& colourSettingsSchema();

// A figure over the stone's pixels: its mean with the mean's standard error, and its spread (standard
// deviation over the pixels) with the spread's standard error (docs/optics.md says how).
struct ColourFigure {
    double mean = 0, meanError = 0, spread = 0, spreadError = 0;
};

// A share with its binomial standard error sqrt(p (1 - p) / N).
struct ColourShare {
    double share = 0, standardError = 0;
};

struct ColourView {
    Illuminant illuminant = Illuminant::D65;
    double sizeMm = 0, headConeDeg = 0, ground = 0, extinctBelowL = 0, saturatedAboveC = 0;
    bool absorbs = false;
    Vec3 white;  // the reference white (the dome seen directly, Y = 1) of CIELAB

    // The picture's pixels, row 0 at the top (+y seen from above), `size` across a square of 2 halfWidthMm:
    // XYZ averaged over the pixel's paths (a path that missed the stone counts 0) and how many met the stone.
    int size = 0, samples = 0, wavelengths = 0;
    double halfWidthMm = 0;
    std::vector<Vec3> xyz;
    std::vector<uint16_t> stoneRays;

    // Over the stone's pixels (those all of whose paths met the stone); rays: paths x wavelengths.
    uint64_t pixels = 0, rays = 0;
    ColourFigure L, a, b, chroma;
    Vec3 meanXyz;  // the area's mean, as a colorimeter over the whole face would see it
    Lab meanLab;
    // View rays that leave through the pavilion or girdle downward (seen through), the error over the paths.
    ColourShare windowed;
    ColourShare extinct;    // pixels with L* below extinctBelowL
    ColourShare saturated;  // pixels with C*ab above saturatedAboveC
    bool cancelled = false;

    bool onStone(size_t pixel) const { return stoneRays[pixel] == samples; }
    Lab lab(size_t pixel) const { return xyzToLab(xyz[pixel], white); }
};

// The face-up colour view of `stone` with the job's material, absorption and size (`settings`; light and
// tilt are the view's own: face-up from above, orthographic). Path s of pixel p draws from
// Rng(seed, p * samples + s) alone, afresh at each wavelength: the same bits at any thread count. Adds each
// pixel to control->done() (the caller starts the phase). Throws Error on bad settings.
ColourView colourView(const Stone& stone, const TraceSettings& settings, const ColourSettings& c,
                      RunControl* control = nullptr);

nlohmann::json toJson(const ColourView& view);

}  // namespace facetlight
