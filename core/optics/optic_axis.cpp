#include "optics/optic_axis.h"

#include <cmath>

namespace facetlight {

using namespace settings;

Vec3 OpticAxisSettings::direction() const {
    const double t = radians(tiltDeg), a = radians(azimuthDeg);
    return {std::sin(t) * std::cos(a), std::sin(t) * std::sin(a), std::cos(t)};
}

std::array<Vec3, 3> OpticAxisSettings::principalAxes() const {
    const double t = radians(tiltDeg), a = radians(azimuthDeg), r = radians(rotationDeg - azimuthDeg);
    // Rz(a) Ry(t) Rz(r) e_x and e_y.
    auto carried = [&](double cx, double cy) {
        const Vec3 v{cx * std::cos(t), cy, -cx * std::sin(t)};  // Ry(t) (cx, cy, 0)
        return Vec3{v.x * std::cos(a) - v.y * std::sin(a), v.x * std::sin(a) + v.y * std::cos(a), v.z};
    };
    const Vec3 x = carried(std::cos(r), std::sin(r)), y = carried(-std::sin(r), std::cos(r));
    return {x, y, direction()};
}

const Schema<OpticAxisSettings>& opticAxisSchema() {
    static const Schema<OpticAxisSettings> schema({
        number(
            "tilt_deg", &OpticAxisSettings::tiltDeg, {.lo = 0, .hi = 180},
            {"--optic-axis-tilt",
             "A doubly refracting stone's optic axis, tilted this far from the table's normal", "degrees"}),
        number("azimuth_deg", &OpticAxisSettings::azimuthDeg, {.lo = 0, .hi = 360, .openHi = true},
               {"--optic-axis-azimuth", "The optic axis's tilt toward this azimuth from the stone's x axis",
                "degrees"}),
        number(
            "rotation_deg", &OpticAxisSettings::rotationDeg, {.lo = 0, .hi = 360, .openHi = true},
            {"--optic-axis-rotation",
             "A biaxial stone's alpha axis (X) turned this far about its gamma axis (Z, placed by the tilt "
             "and azimuth)",
             "degrees"}),
    });
    return schema;
}

}  // namespace facetlight
