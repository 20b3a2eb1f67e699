#pragma once
// The CIE's colorimetric tables (docs/optics.md, "Colour"): the CIE 1931 2-degree standard observer's colour
// matching functions and the relative spectral power of CIE standard illuminants D65 (tabulated) and A
// (Planck's law as CIE 015:2018 defines it), with tristimulus values summed as CIE 015:2018 section 7 says.
#include <functional>

#include "geometry/geometry.h"
#include "util/name_table.h"

namespace facetlight {

// The tables' range and step: CIE 015:2018 sums at 5 nm from 380 to 780 nm.
constexpr double kCieFirstNm = 380, kCieLastNm = 780, kCieStepNm = 5;

// x-bar, y-bar, z-bar at a wavelength: a Catmull-Rom curve through the table's rows (it passes through every
// tabulated value); 0 outside 380-780 nm.
Vec3 cieXyz(double wavelengthNm);

enum class Illuminant { D65, A };
inline constexpr NameTable<Illuminant, 2> kIlluminantNames{
    {{{Illuminant::D65, "D65"}, {Illuminant::A, "A"}}}};

// The illuminant's relative spectral power, 100 at 560 nm: D65 linear between its 5 nm rows (as CIE 015
// recommends for D65), A from its formula; 0 outside 380-780 nm.
double illuminantPower(Illuminant illuminant, double wavelengthNm);

// The tristimulus values of light from `illuminant` passed on by `factor` (a transmittance or reflectance
// against wavelength): X = k sum S(l) factor(l) x-bar(l) over the tables' rows, k = 1 / sum S(l) y-bar(l), so
// that factor 1 (the perfect white) has Y = 1 (CIE 015:2018, 7.1 and 7.2).
Vec3 tristimulus(Illuminant illuminant, const std::function<double(double)>& factor);
Vec3 whitePoint(Illuminant illuminant);  // tristimulus() of factor 1

}  // namespace facetlight
