#pragma once
// Where a doubly refracting stone's optic axis points (docs/optics.md, "Birefringent stones"), described once
// in opticAxisSchema(): JSON "optic_axis" of a job, CLI flags and the API schema follow from it.
#include "geometry/geometry.h"
#include "settings/settings_schema.h"

namespace facetlight {

struct OpticAxisSettings {
    // The axis tilted this far from the table's normal (the stone's +z), toward this azimuth from the stone's x
    // axis toward y. The default, along the table's normal, is how sapphire and tourmaline are usually cut
    // for the purest face-up colour.
    double tiltDeg = 0;
    double azimuthDeg = 0;

    // The unit axis in the stone's frame.
    Vec3 direction() const;
};

const settings::Schema<OpticAxisSettings>& opticAxisSchema();

}  // namespace facetlight
