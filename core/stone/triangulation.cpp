#include "stone/triangulation.h"

#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <string>

#include "stone/detail/newell.h"
#include "util/error.h"

namespace facetlight {

namespace {

// Ear clipping in the polygon's own plane; ears of zero area are never cut, so vertices lying on an edge
// (shared with a neighbouring facet) stay in the mesh without creating degenerate triangles.
void clipEars(const std::vector<Vec3>& points, const std::vector<uint32_t>& loop, const Vec3& normal,
              double areaEps, size_t polygonIndex, std::vector<std::array<uint32_t, 3>>& out) {
    const Vec3 helper = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalize(cross(helper, normal));
    const Vec3 w = cross(normal, u);
    struct P2 {
        double x, y;
    };
    std::vector<P2> p(loop.size());
    for (size_t i = 0; i < loop.size(); ++i) p[i] = {dot(points[loop[i]], u), dot(points[loop[i]], w)};
    auto area2 = [&](size_t a, size_t b, size_t c) {
        return (p[b].x - p[a].x) * (p[c].y - p[a].y) - (p[b].y - p[a].y) * (p[c].x - p[a].x);
    };
    std::vector<size_t> ring(loop.size());
    std::iota(ring.begin(), ring.end(), 0);
    while (ring.size() > 3) {
        bool cut = false;
        for (size_t i = 0; i < ring.size() && !cut; ++i) {
            const size_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
                         c = ring[(i + 1) % ring.size()];
            if (area2(a, b, c) <= 2 * areaEps) continue;
            bool inside = false;
            for (size_t q : ring) {
                if (q == a || q == b || q == c) continue;
                if (area2(a, b, q) >= 0 && area2(b, c, q) >= 0 && area2(c, a, q) >= 0 &&
                    (p[q].x != p[a].x || p[q].y != p[a].y) && (p[q].x != p[c].x || p[q].y != p[c].y)) {
                    inside = true;
                    break;
                }
            }
            if (inside) continue;
            out.push_back({loop[a], loop[b], loop[c]});
            ring.erase(ring.begin() + long(i));
            cut = true;
        }
        if (!cut)
            throw Error("face " + std::to_string(polygonIndex + 1) + " is self-intersecting or degenerate");
    }
    if (area2(ring[0], ring[1], ring[2]) <= 2 * areaEps)
        throw Error("face " + std::to_string(polygonIndex + 1) + " is degenerate (zero area)");
    out.push_back({loop[ring[0]], loop[ring[1]], loop[ring[2]]});
}

struct Welded {
    std::vector<Vec3> vertices;
    std::vector<uint32_t> remap;
};

Welded weldExactDuplicates(const std::vector<Vec3>& in) {
    Welded w;
    w.remap.resize(in.size());
    std::map<std::array<uint64_t, 3>, uint32_t> seen;
    for (size_t i = 0; i < in.size(); ++i) {
        std::array<uint64_t, 3> key;
        const double c[3] = {in[i].x + 0.0, in[i].y + 0.0, in[i].z + 0.0};  // + 0.0 folds -0 into 0
        std::memcpy(key.data(), c, sizeof c);
        auto [it, inserted] = seen.emplace(key, uint32_t(w.vertices.size()));
        if (inserted) w.vertices.push_back(in[i]);
        w.remap[i] = it->second;
    }
    return w;
}

}  // namespace

Triangulation triangulate(const PolygonMesh& mesh, double scale) {
    Triangulation out;
    Welded welded = weldExactDuplicates(mesh.vertices);
    out.vertices = std::move(welded.vertices);
    const double areaEps = 1e-14 * scale * scale;
    std::vector<std::array<uint32_t, 3>> tris;
    for (size_t f = 0; f < mesh.polygons.size(); ++f) {
        std::vector<uint32_t> loop;
        for (uint32_t v : mesh.polygons[f].vertices) {
            const uint32_t w = welded.remap[v];
            if (loop.empty() || loop.back() != w) loop.push_back(w);
        }
        while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
        const Vec3 n = detail::newellNormal(out.vertices, loop);
        if (loop.size() < 3 || length(n) <= 2 * areaEps)
            throw Error("face " + std::to_string(f + 1) + " is degenerate (zero area)");
        tris.clear();
        clipEars(out.vertices, loop, normalize(n), areaEps, f, tris);
        for (const auto& t : tris) {
            out.triangles.push_back({t, 0});
            out.source.push_back(uint32_t(f));
        }
    }
    return out;
}

}  // namespace facetlight
