#include "stone/stone_size.h"

#include <cmath>

#include "util/error.h"

namespace facetlight {

StoneSize stoneSize(const Stone& stone, double sizeMm, std::optional<double> densityGcm3) {
    const double diameter = stone.proportions.diameter;
    if (!(diameter > 0)) throw Error("stone '" + stone.name + "' has no girdle width to scale to a size");
    if (!(sizeMm > 0) || !std::isfinite(sizeMm)) throw Error("the size must be a positive number of mm");
    const double mm = sizeMm / diameter;
    StoneSize s;
    s.lengthMm = stone.proportions.length * mm;
    s.widthMm = stone.proportions.width * mm;
    s.depthMm = stone.bounds.extent().z * mm;
    s.volumeMm3 = stone.volume() * mm * mm * mm;
    const Vec3 block = stone.bounds.extent();
    s.blockRetention = stone.volume() / (block.x * block.y * block.z);
    if (densityGcm3) s.carats = s.volumeMm3 * 1e-3 * *densityGcm3 / 0.2;
    return s;
}

double roughRetention(const Stone& stone, const Stone& rough) {
    if (!stone.frame.fileOrientation || !rough.frame.fileOrientation)
        throw Error("the stone and the rough must keep their files' orientation to be compared");
    if (!(rough.volume() > 0)) throw Error("the rough '" + rough.name + "' has no volume");
    if (rough.convex) {
        const double tolerance = 1e-6 * length(rough.bounds.extent());
        for (const Vec3& v : stone.vertices) {
            const Vec3 p = v + stone.frame.shift - rough.frame.shift;  // the stone's vertex in the rough's frame
            for (const Facet& f : rough.facets) {
                const double out = dot(f.normal, p) - f.offset;
                if (out > tolerance)
                    throw Error("the stone does not fit inside the rough '" + rough.name + "': a corner lies " +
                                std::to_string(out) + " outside its facet " + f.name);
            }
        }
    }
    return stone.volume() / rough.volume();
}

}  // namespace facetlight
