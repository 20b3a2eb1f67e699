#include "stone/stone.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <unordered_map>

#include "stone/detail/edge_map.h"
#include "stone/detail/newell.h"
#include "stone/girdle.h"
#include "stone/mesh_checks.h"
#include "stone/proportions.h"
#include "stone/standard_frame.h"
#include "stone/triangulation.h"
#include "util/error.h"

namespace facetlight {

std::string_view regionName(Region r) {
    switch (r) {
        case Region::Table: return "table";
        case Region::Crown: return "crown";
        case Region::Girdle: return "girdle";
        case Region::Pavilion: return "pavilion";
    }
    return "unknown";
}

int Stone::facetCount(Region r) const {
    return int(std::count_if(facets.begin(), facets.end(), [r](const Facet& f) { return f.region == r; }));
}

double Stone::volume() const {
    double v = 0;
    for (const auto& t : triangles)
        v += dot(vertices[t.v[0]], cross(vertices[t.v[1]], vertices[t.v[2]]));
    return v / 6.0;
}

namespace {

// The steps of Stone::build() that group the triangles into facets and name their regions; the checks, the
// orientation and the measurements are steps of their own.
class StoneBuilder {
public:
    StoneBuilder(const PolygonMesh& mesh, const StoneOptions& options) : mesh_(mesh), options_(options) {}

    Stone build(std::string name) {
        stone_.name = std::move(name);
        stone_.warnings = mesh_.warnings;
        scale_ = checkMeshInput(mesh_, options_.limits);
        Triangulation triangulation = triangulate(mesh_, scale_);
        stone_.vertices = std::move(triangulation.vertices);
        stone_.triangles = std::move(triangulation.triangles);
        triangleSource_ = std::move(triangulation.source);
        checkClosedAndOrient(stone_, triangleSource_, scale_);
        mergeFacets();
        stone_.design = mesh_.design;
        if (options_.standardFrame) moveToStandardFrame(stone_, scale_, !(mesh_.design || options_.keepFrame));
        finishFacets();
        classifyRegions();
        stone_.proportions = measureProportions(stone_, scale_);
        // A design is the intersection of its facets' half-spaces: convex by construction, though welding its
        // meets may bend an outline by the printed precision.
        stone_.convex = mesh_.design || isConvex(stone_, directed_, scale_);
        return std::move(stone_);
    }

  private:
    // Grows facets over edge-connected triangles lying in the seed triangle's plane. A GemCad design's polygon
    // is one facet whatever its corners: welding its meets to the printed precision (io/gemcad_design.h) may
    // move them off its plane by that much.
    void mergeFacets() {
        const size_t nt = stone_.triangles.size();
        detail::EdgeMap& directed = directed_;
        for (uint32_t t = 0; t < nt; ++t)
            for (int k = 0; k < 3; ++k) directed[{stone_.triangles[t].v[k], stone_.triangles[t].v[(k + 1) % 3]}] = t;
        const double distEps = 1e-7 * scale_;
        std::vector<int64_t> facetOf(nt, -1);
        for (uint32_t seed = 0; seed < nt; ++seed) {
            if (facetOf[seed] >= 0) continue;
            const auto& sv = stone_.triangles[seed].v;
            // The plane of the seed's whole input polygon (Newell), not of the seed triangle, which may be a
            // sliver with an unreliable normal.
            const Vec3 seedCross = cross(stone_.vertices[sv[1]] - stone_.vertices[sv[0]],
                                         stone_.vertices[sv[2]] - stone_.vertices[sv[0]]);
            const Vec3 polygonNormal =
                detail::newellNormal(mesh_.vertices, mesh_.polygons[triangleSource_[seed]].vertices);
            const Vec3 n = normalize(dot(polygonNormal, seedCross) < 0 ? -polygonNormal : polygonNormal);
            const double d = dot(n, stone_.vertices[sv[0]]);
            const uint32_t id = uint32_t(stone_.facets.size());
            Facet facet;
            facet.id = id;
            std::vector<uint32_t> stack{seed};
            facetOf[seed] = id;
            while (!stack.empty()) {
                const uint32_t t = stack.back();
                stack.pop_back();
                facet.triangles.push_back(t);
                const auto& v = stone_.triangles[t].v;
                for (int k = 0; k < 3; ++k) {
                    const uint32_t o = directed.at({v[(k + 1) % 3], v[k]});
                    if (facetOf[o] >= 0) continue;
                    bool coplanar = true;
                    for (uint32_t ov : stone_.triangles[o].v)
                        coplanar &= std::fabs(dot(n, stone_.vertices[ov]) - d) <= distEps;
                    const auto& q = stone_.triangles[o].v;
                    const Vec3 on = cross(stone_.vertices[q[1]] - stone_.vertices[q[0]],
                                          stone_.vertices[q[2]] - stone_.vertices[q[0]]);
                    const bool onePolygon = mesh_.design && triangleSource_[o] == triangleSource_[t];
                    if (onePolygon || (coplanar && dot(on, n) > 0)) {
                        facetOf[o] = id;
                        stack.push_back(o);
                    }
                }
            }
            std::sort(facet.triangles.begin(), facet.triangles.end());
            for (uint32_t t : facet.triangles) {
                stone_.triangles[t].facet = id;
                if (facet.name.empty()) facet.name = mesh_.polygons[triangleSource_[t]].name;
            }
            facet.outline = outlineOf(facet, directed);
            stone_.facets.push_back(std::move(facet));
        }
    }

    std::vector<uint32_t> outlineOf(const Facet& facet, const detail::EdgeMap& directed) const {
        // Boundary edges are those whose reverse belongs to another facet; chain the longest loop.
        std::unordered_map<uint32_t, uint32_t> next;
        for (uint32_t t : facet.triangles) {
            const auto& v = stone_.triangles[t].v;
            for (int k = 0; k < 3; ++k) {
                const uint32_t a = v[k], b = v[(k + 1) % 3];
                const uint32_t o = directed.at({b, a});
                if (!std::binary_search(facet.triangles.begin(), facet.triangles.end(), o)) next[a] = b;
            }
        }
        std::vector<uint32_t> best;
        std::unordered_map<uint32_t, bool> used;
        for (const auto& [start, unused] : next) {
            if (used[start]) continue;
            std::vector<uint32_t> loop;
            uint32_t v = start;
            while (!used[v] && next.count(v)) {
                used[v] = true;
                loop.push_back(v);
                v = next.at(v);
            }
            if (loop.size() > best.size()) best = std::move(loop);
        }
        return best;
    }

    void finishFacets() {
        std::map<std::string, int> nameCount;
        for (const auto& f : stone_.facets) ++nameCount[f.name];
        std::map<std::string, int> nameIndex;
        for (auto& f : stone_.facets) {
            Vec3 areaVector, weighted;
            for (uint32_t t : f.triangles) {
                const auto& v = stone_.triangles[t].v;
                const Vec3 &a = stone_.vertices[v[0]], &b = stone_.vertices[v[1]], &c = stone_.vertices[v[2]];
                const Vec3 ac = cross(b - a, c - a);
                areaVector += ac;
                weighted += (a + b + c) * (length(ac) / 3.0);
            }
            // Newell's method over the outline agrees with the triangle sum for planar facets; both avoid
            // the normal of three possibly collinear vertices.
            const Vec3 newell = detail::newellNormal(stone_.vertices, f.outline);
            const Vec3 n = length(newell) > 0 ? newell : areaVector;
            f.normal = normalize(n);
            f.area = 0.5 * length(areaVector);
            f.centroid = weighted / (2 * f.area);
            f.offset = dot(f.normal, f.centroid);
            if (!isFinite(f.normal) || !isFinite(f.centroid) || !std::isfinite(f.offset) || !(f.area > 0))
                throw Error("facet " + std::to_string(f.id + 1) + " has no finite normal, area or centre");
            if (f.name.empty())
                f.name = "facet_" + std::to_string(f.id + 1);
            else if (nameCount[f.name] > 1)
                f.name += "_" + std::to_string(++nameIndex[f.name]);
        }
    }

    void classifyRegions() {
        stone_.bounds = {};
        for (const auto& v : stone_.vertices) stone_.bounds.extend(v);
        const double top = stone_.bounds.hi.z;
        const double eps = 1e-7 * scale_;
        for (auto& f : stone_.facets) {
            if (isGirdleNormal(f.normal))
                f.region = Region::Girdle;
            else if (f.normal.z > 1 - 1e-6 && std::fabs(f.offset - top) <= eps)
                f.region = Region::Table;
            else
                f.region = f.normal.z > 0 ? Region::Crown : Region::Pavilion;
        }
    }

    const PolygonMesh& mesh_;
    const StoneOptions& options_;
    Stone stone_;
    detail::EdgeMap directed_;
    std::vector<uint32_t> triangleSource_;  // input polygon of each triangle, for messages and names
    double scale_ = 0;
};

}  // namespace

Stone Stone::build(const PolygonMesh& mesh, std::string name, const StoneOptions& options) {
    return StoneBuilder(mesh, options).build(std::move(name));
}

}  // namespace facetlight
