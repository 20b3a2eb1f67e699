#pragma once
// Where a doubly refracting stone's optic axis points (docs/optics.md, "Birefringent stones"), or a biaxial
// one's principal axes ("Biaxial crystals"), described once in opticAxisSchema(): JSON "optic_axis" of a job,
// CLI flags and the API schema follow from it.
#include <array>

#include "geometry/geometry.h"
#include "settings/settings_schema.h"

namespace facetlight {

struct OpticAxisSettings {
    // The axis tilted this far from the table's normal (the stone's +z), toward this azimuth from the stone's x
    // axis toward y. The default, along the table's normal, is how sapphire and tourmaline are usually cut
    // for the purest face-up colour.
    double tiltDeg = 0;
    double azimuthDeg = 0;
    // A biaxial stone's axes: tilt and azimuth place its Z (the gamma axis), and X (alpha) lies this far
    // about Z from where the same tilt carries the stone's x axis (the turn about the horizontal line across
    // the azimuth that takes +z to Z); Y = Z x X. Uniaxial and isotropic stones refuse anything but 0.
    double rotationDeg = 0;

    // The unit axis in the stone's frame (a biaxial stone's Z).
    Vec3 direction() const;
    // A biaxial stone's principal axes X, Y, Z in the stone's frame: Rz(azimuth) Ry(tilt) Rz(rotation -
    // azimuth) applied to the stone's x, y, z.
    std::array<Vec3, 3> principalAxes() const;
};

const settings::Schema<OpticAxisSettings>& opticAxisSchema();

}  // namespace facetlight
