#include "cuts/facet_design.h"

#include <cmath>
#include <cstdio>
#include <set>

#include "util/error.h"

namespace facetlight {

NamedPlane facetPlane(std::string name, double azimuthDeg, double slopeDeg, bool up, const Vec3& through) {
    const double az = radians(azimuthDeg), slope = radians(slopeDeg);
    const Vec3 n{std::sin(slope) * std::cos(az), std::sin(slope) * std::sin(az),
                 up ? std::cos(slope) : -std::cos(slope)};
    return {{n, dot(n, through)}, std::move(name)};
}

Vec3 polar(double radius, double azimuthDeg, double z) {
    return {radius * std::cos(radians(azimuthDeg)), radius * std::sin(radians(azimuthDeg)), z};
}

PolygonMesh intersectDesign(const std::vector<NamedPlane>& planes, const std::string& hint) {
    PolygonMesh mesh = intersectHalfSpaces(planes);
    std::set<std::string> present;
    for (const auto& poly : mesh.polygons) present.insert(poly.name);
    for (const auto& plane : planes)
        if (plane.name.rfind("girdle_", 0) != 0 && !present.count(plane.name))
            throw Error("these proportions leave no room for the facet '" + plane.name + "': " + hint);
    return mesh;
}

std::string formatNumber(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

}  // namespace facetlight
