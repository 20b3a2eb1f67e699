#include "optics/optic_axis.h"

#include <cmath>

namespace facetlight {

using namespace settings;

Vec3 OpticAxisSettings::direction() const {
    const double t = radians(tiltDeg), a = radians(azimuthDeg);
    return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
}

const Schema<OpticAxisSettings>& opticAxisSchema() {
    static const Schema<OpticAxisSettings> schema({
        number("tilt_deg", &OpticAxisSettings::tiltDeg, {.lo = 0, .hi = 180},
               {"--optic-axis-tilt",
                "A doubly refracting stone's optic axis, tilted this far from the table's normal", "degrees"}),
        number("azimuth_deg", &OpticAxisSettings::azimuthDeg, {.lo = 0, .hi = 360, .openHi = true},
               {"--optic-axis-azimuth", "The optic axis's tilt toward this azimuth from the stone's x axis",
                "degrees"}),
    });
    return schema;
}

}  // namespace facetlight
