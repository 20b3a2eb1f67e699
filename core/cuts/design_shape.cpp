#include "cuts/design_shape.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "cuts/facet_design.h"
#include "util/bounded_read.h"
#include "util/error.h"

namespace facetlight {

namespace {

// A tier's slope stays strictly between the table (0) and the girdle (90): those two are not tweaked.
constexpr double kMinTierSlope = 1, kMaxTierSlope = 89;

// The meet a facet keeps: its polygon's vertex farthest from the z axis; for a facet that does not reach the
// surface, the point of its plane nearest the centre.
Vec3 keptMeet(const PolygonMesh& built, const PolygonMesh::Polygon* polygon, const Plane& plane) {
    if (!polygon) return plane.normal * plane.offset;
    Vec3 best = built.vertices[polygon->vertices[0]];
    for (uint32_t v : polygon->vertices) {
        const Vec3& p = built.vertices[v];
        if (std::hypot(p.x, p.y) > std::hypot(best.x, best.y) + 1e-12) best = p;
    }
    return best;
}

}  // namespace

GemCadDesign retier(const GemCadDesign& design, const PolygonMesh& built, const CutValues& values) {
    GemCadDesign out = design;
    if (values.empty()) return out;
    const std::vector<NamedPlane> planes = gemCadPlanes(design);
    std::map<std::string, const PolygonMesh::Polygon*> polygonOf;
    for (const auto& p : built.polygons) polygonOf[p.name] = &p;
    size_t plane = 0;
    for (size_t t = 0; t < design.tiers.size(); ++t) {
        const GemCadTier& tier = design.tiers[t];
        const auto value = values.find(tierParameter(design, t));
        if (value == values.end() || !tweakableTier(tier) || value->second == std::fabs(tier.angleDeg)) {
            plane += tier.facets.size();
            continue;
        }
        GemCadTier& recut = out.tiers[t];
        recut.angleDeg = tier.pavilion() ? -value->second : value->second;
        // One distance for the tier, as GemCad keeps it: the largest its facets' meets ask for, so that no
        // facet cuts past the meet it keeps (for a symmetric tier they all ask the same).
        double distance = -INFINITY;
        for (const GemCadFacet& f : tier.facets) {
            const auto it = polygonOf.find(planes[plane].name);
            const Vec3 meet = keptMeet(built, it == polygonOf.end() ? nullptr : it->second, planes[plane].plane);
            distance = std::max(distance, dot(gemCadNormal(recut.angleDeg, gemCadAzimuthDeg(design, f.index)), meet));
            ++plane;
        }
        if (!(distance > 0))
            throw Error(tierParameter(design, t) + " " + formatNumber(value->second) +
                        ": at this slope the tier would pass the stone's centre on the other side of its meet");
        recut.distance = distance;
    }
    return out;
}

GemCadDesign FileShape::designAt(const CutValues& values) const {
    if (!design) throw Error(shape.name + " is a mesh, not a GemCad design: it has no tiers to write");
    return retier(*design, *built, values);
}

std::shared_ptr<const FileShape> fileShape(const std::string& path, const MeshLimits& limits) {
    try {
        const std::string bytes = readFileUpTo(path, limits.maxFileBytes, "stone file");
        const MeshFormat format = formatFromFileName(path).value_or(detectFormat(bytes));
        auto file = std::make_shared<FileShape>();
        file->shape.name = std::filesystem::path(path).stem().string();
        file->shape.description = "the design in " + path;
        if (format == MeshFormat::GemCad || format == MeshFormat::GemCadBinary) {
            auto design = std::make_shared<const GemCadDesign>(format == MeshFormat::GemCad
                                                                   ? parseGemCadDesign(bytes, limits)
                                                                   : parseGemCadBinary(bytes, limits));
            auto built = std::make_shared<const PolygonMesh>(buildGemCadMesh(*design, limits));
            for (size_t t = 0; t < design->tiers.size(); ++t) {
                const GemCadTier& tier = design->tiers[t];
                if (!tweakableTier(tier)) continue;
                file->shape.parameters.push_back(
                    {tierParameter(*design, t), "deg",
                     "slope of the " + std::string(tier.pavilion() ? "pavilion" : "crown") + " tier " + tier.name,
                     std::fabs(tier.angleDeg), kMinTierSlope, kMaxTierSlope});
            }
            file->shape.build = [design, built, limits](const CutValues& values) {
                return buildGemCadMesh(retier(*design, *built, values), limits);
            };
            file->design = std::move(design);
            file->built = std::move(built);
        } else {
            auto mesh = std::make_shared<const PolygonMesh>(parseMesh(bytes, format, limits));
            file->shape.build = [mesh](const CutValues&) { return *mesh; };
            file->built = std::move(mesh);
        }
        return file;
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
}

}  // namespace facetlight
