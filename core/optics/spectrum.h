#pragma once
// Colour from wavelengths for the renderer and the tracer: the visible range photons are drawn from, its
// bands of equal colour-matching weight and a photon's colour (the tables themselves in colour/cie.h).
#include <vector>

#include "colour/cie.h"
#include "geometry/geometry.h"

namespace facetlight {

// The visible range the tracer draws photon wavelengths from.
constexpr double kMinWavelength = 380, kMaxWavelength = 780;

// The visible range cut into `count` bands of equal colour-matching weight (x + y + z), each with the linear
// sRGB colour of its share of an equal-energy white, white-balanced so that the colours of all bands add up
// to (1, 1, 1) exactly. A renderer gives each sample one band and a wavelength inside it: paths that do not
// depend on wavelength then add up to exact greys, and dispersion shows in `count` hues.
class SpectralBands {
  public:
    explicit SpectralBands(int count);
    int count() const { return int(colour_.size()); }
    // A wavelength in band b, u in [0, 1) placing it within the band.
    double wavelength(int band, double u) const { return edge_[band] + u * (edge_[band + 1] - edge_[band]); }
    const Vec3& colour(int band) const { return colour_[band]; }

  private:
    std::vector<double> edge_;  // count + 1 band edges in nm
    std::vector<Vec3> colour_;
};

// The linear sRGB colour of a photon of `wavelengthNm`, scaled so that photons spread evenly over the visible
// range average to (1, 1, 1): a photon map's power in this colour adds up to white for white light.
Vec3 photonColour(double wavelengthNm);

}  // namespace facetlight
