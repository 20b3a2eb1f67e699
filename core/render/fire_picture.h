#pragma once
// The fire picture (docs/physics.md, "Fire picture"): the stone through the render's camera under one small
// bright light (a disc of a given angular radius, tilted from the vertical) in a dim room (the studio's light
// scaled down, so that the stone's outline reads), in true spectral colour. Each pixel traces `wavelengths`
// camera rays, ray s at a wavelength drawn in the s-th of as many equal strata of 380-730 nm and refracted
// with the material's n at that wavelength, and adds their light times the CIE 1931 colour matching functions
// (optics/spectrum.h): where red and blue leave the stone in different directions, one reaches the light and
// the other does not, and the pixel shows the colour of the wavelengths that did.
//
// The rays are the renderer's (render/detail/sample_tracer.h). Pixel p draws from Rng(seed, p) alone: the
// picture is the same bits for any thread count.
#include <cstdint>
#include <vector>

#include "geometry/geometry.h"
#include "image/image.h"
#include "render/render_settings.h"
#include "scene/scene.h"
#include "util/run_control.h"

namespace facetlight {

// The traced range: the colour matching functions are below 1e-4 of their peak outside it.
constexpr double kFireMinWavelength = 380, kFireMaxWavelength = 730;

// CIE XYZ per pixel, row by row from the top, of light whose spectrum is measured in units where the
// light's disc gives unit irradiance at every wavelength.
struct FirePicture {
    int width = 0, height = 0;
    std::vector<Vec3> xyz;
    bool cancelled = false;
};

// At the render's size, camera and bounce limit. Advances control->done() by the pixels of each row. Throws
// Error on bad settings.
FirePicture firePicture(const Scene& scene, const RenderSettings& render, const FirePictureSettings& settings,
                        int threads, uint64_t seed, RunControl* control = nullptr);

// XYZ to linear sRGB (IEC 61966-2-1), white-balanced so that light of an equal-energy spectrum over the
// traced range comes out grey (R = G = B): the light is shown as white.
Vec3 balancedSrgb(const Vec3& xyz);

// The display image: balancedSrgb, an exposure that maps the 95th percentile of the luminance of the pixels
// that see any light to 0.5, out-of-gamut (negative) channels clipped to 0, any channel above 1 brought to 1
// by scaling the pixel down (keeping its hue), then the sRGB curve. The light is hundreds of times brighter
// than the room, and its flashes cover a few per cent of the picture at most: the percentile falls on the
// room's reflections, which then read as greys, and the flashes saturate in their own colours.
Image toDisplay(const FirePicture& picture);
constexpr double kFireExposurePercentile = 95, kFireExposureLevel = 0.2;

}  // namespace facetlight
