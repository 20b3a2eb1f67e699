#pragma once
// Colour spaces from CIE XYZ (docs/optics.md, "Colour"): linear sRGB and its transfer curve (IEC 61966-2-1),
// and CIELAB (CIE 015:2018, 8.2.1) against a reference white.
#include "geometry/geometry.h"

namespace facetlight {

// XYZ (Y = 1 for the white) to linear sRGB, whose white is D65.
Vec3 xyzToLinearSrgb(const Vec3& xyz);
// Linear sRGB (white (1, 1, 1)) to XYZ with Y = 1 for the white.
Vec3 linearSrgbToXyz(const Vec3& rgb);
// Linear [0, 1] to the sRGB-encoded [0, 1] value (clamped).
double srgbEncode(double linear);
// The sRGB-encoded [0, 1] value to linear (IEC 61966-2-1's decoding).
double srgbDecode(double encoded);

struct Lab {
    double L = 0, a = 0, b = 0;
    double chroma() const;  // C*ab = sqrt(a^2 + b^2)
    double hueDeg() const;  // h_ab in [0, 360)
};
// CIELAB of `xyz` against the reference white `white` (its Y the scale of xyz's Y).
Lab xyzToLab(const Vec3& xyz, const Vec3& white);
// The CIE 1976 colour difference Delta E*ab: the distance in CIELAB.
double deltaE(const Lab& x, const Lab& y);

}  // namespace facetlight
