#pragma once
// "Colour by transmission" (docs/optics.md): where no absorption spectrum is published, the colour a known
// path through the stone transmits, turned into a smooth spectrum. An approximation: many spectra transmit
// one colour (metamers), and this picks the smoothest of one family, which says nothing of narrow bands.
#include <string>
#include <vector>

#include "colour/colour_space.h"

namespace facetlight {

// CIELAB under D65, against D65's white, of the light `pathMm` of the stone transmits (no surface
// reflection). Returns alpha per mm at kTransmissionWavelengthsNm: T = exp(-alpha pathMm) is Jakob & Hanika's
// smooth spectrum, a sigmoid of a quadratic in wavelength (Computer Graphics Forum 38(2), 2019), fitted so
// that T transmits `target` to within Delta E*ab 0.05. Throws Error (naming `field`) for a colour no such
// spectrum transmits (brighter than its chroma allows, or outside the colours a filter can show).
std::vector<double> absorptionForTransmittedColour(const Lab& target, double pathMm,
                                                   const std::string& field);
extern const std::vector<double> kTransmissionWavelengthsNm;  // 380-780 nm every 10 nm

// "#rrggbb" (sRGB, IEC 61966-2-1) as CIELAB against sRGB's own D65 white: #ffffff is L* 100, a* b* 0.
Lab srgbHexToLab(const std::string& hex, const std::string& field);

}  // namespace facetlight
