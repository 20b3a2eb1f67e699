#include "geometry/halfspace.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "util/error.h"

namespace facetlight {

namespace {

// A convex polyhedron with shared vertices, so that an edge split by a plane is split once and both
// polygons on that edge get the same new vertex: no cracks, no T-junctions.
struct Polyhedron {
    std::vector<Vec3> vertices;
    std::vector<PolygonMesh::Polygon> faces;
};

constexpr const char* kBoxFace = "\x01box";

Polyhedron makeBox(double h) {
    Polyhedron p;
    for (int i = 0; i < 8; ++i) p.vertices.push_back({i & 1 ? h : -h, i & 2 ? h : -h, i & 4 ? h : -h});
    const uint32_t quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) p.faces.push_back({{q[0], q[1], q[2], q[3]}, kBoxFace});
    return p;
}

// Orders points lying on a plane counter-clockwise seen from the side its normal points to.
void sortAroundNormal(std::vector<uint32_t>& loop, const std::vector<Vec3>& vertices, const Vec3& normal) {
    Vec3 c;
    for (uint32_t v : loop) c += vertices[v];
    c = c / double(loop.size());
    const Vec3 helper = std::fabs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
    const Vec3 u = normalize(cross(helper, normal));
    const Vec3 w = cross(normal, u);
    std::vector<std::pair<double, uint32_t>> keyed;
    for (uint32_t v : loop) {
        const Vec3 d = vertices[v] - c;
        keyed.push_back({std::atan2(dot(d, w), dot(d, u)), v});
    }
    std::sort(keyed.begin(), keyed.end());
    for (size_t i = 0; i < loop.size(); ++i) loop[i] = keyed[i].second;
}

// Clips a solid by one plane after another. The scratch arrays live as long as the clipper, and a face the
// plane does not cross is kept as it is: a design of many facets clips in time close to linear in its faces.
class Clipper {
  public:
    explicit Clipper(double eps) : eps_(eps) {}

    void clip(Polyhedron& solid, const NamedPlane& cut) {
        const size_t n = solid.vertices.size();
        d_.resize(n);
        bool anyOut = false, anyIn = false;
        for (size_t i = 0; i < n; ++i) {
            d_[i] = cut.plane.signedDistance(solid.vertices[i]);
            anyOut |= d_[i] > eps_;
            anyIn |= d_[i] < -eps_;
        }
        if (!anyIn) throw Error("the facets enclose no volume (facet '" + cut.name + "' cuts the whole stone away)");
        if (!anyOut) return;  // the plane misses the solid or only touches it

        splitEdges_.clear();
        onCap_.assign(n, false);
        auto isOut = [&](uint32_t v) { return v < n && d_[v] > eps_; };
        auto isIn = [&](uint32_t v) { return v < n && d_[v] < -eps_; };
        size_t kept = 0;
        for (auto& face : solid.faces) {
            const bool crossed = std::any_of(face.vertices.begin(), face.vertices.end(), isOut);
            if (crossed) {
                PolygonMesh::Polygon out{{}, face.name};
                const size_t m = face.vertices.size();
                for (size_t i = 0; i < m; ++i) {
                    const uint32_t a = face.vertices[i], b = face.vertices[(i + 1) % m];
                    if (!isOut(a)) out.vertices.push_back(a);
                    if ((isIn(a) && isOut(b)) || (isOut(a) && isIn(b)))
                        out.vertices.push_back(splitVertex(solid, a, b));
                }
                if (out.vertices.size() < 3) continue;
                face = std::move(out);
            }
            for (uint32_t v : face.vertices)
                if (v < n && !isIn(v)) onCap_[v] = true;
            if (&solid.faces[kept] != &face) solid.faces[kept] = std::move(face);
            ++kept;
        }
        solid.faces.resize(kept);

        // The cap's corners: the old vertices on the plane, then the new ones in the order of the edges they
        // split (sortAroundNormal breaks ties by this order).
        std::vector<uint32_t> cap;
        for (size_t v = 0; v < n; ++v)
            if (onCap_[v]) cap.push_back(uint32_t(v));
        std::sort(splitEdges_.begin(), splitEdges_.end());
        for (const auto& [edge, v] : splitEdges_) cap.push_back(v);
        if (cap.size() >= 3) {
            sortAroundNormal(cap, solid.vertices, cut.plane.normal);
            solid.faces.push_back({std::move(cap), cut.name});
        }
    }

  private:
    // The vertex where the plane splits edge ab, made once for both faces along the edge.
    uint32_t splitVertex(Polyhedron& solid, uint32_t a, uint32_t b) {
        const std::pair<uint32_t, uint32_t> key = std::minmax(a, b);
        for (const auto& [edge, v] : splitEdges_)
            if (edge == key) return v;
        const double t = d_[key.first] / (d_[key.first] - d_[key.second]);
        const Vec3 p = solid.vertices[key.first] + (solid.vertices[key.second] - solid.vertices[key.first]) * t;
        solid.vertices.push_back(p);
        const uint32_t id = uint32_t(solid.vertices.size() - 1);
        splitEdges_.push_back({key, id});
        return id;
    }

    double eps_;
    std::vector<double> d_;
    std::vector<bool> onCap_;
    std::vector<std::pair<std::pair<uint32_t, uint32_t>, uint32_t>> splitEdges_;
};

}  // namespace

PolygonMesh intersectHalfSpaces(const std::vector<NamedPlane>& planes, double weld) {
    if (planes.size() < 4) throw Error("a closed stone needs at least 4 facet planes, got " + std::to_string(planes.size()));
    double reach = 0;
    for (const auto& p : planes) {
        if (!isFinite(p.plane.normal) || !std::isfinite(p.plane.offset))
            throw Error("facet '" + p.name + "' has a non-finite plane");
        if (std::fabs(p.plane.offset) > kMaxMeshCoordinate)
            throw Error("facet '" + p.name + "' lies too far from the centre (beyond " +
                        std::to_string(int64_t(kMaxMeshCoordinate)) + ")");
        const double len = length(p.plane.normal);
        if (!(len > 0.5 && len < 2.0)) throw Error("facet '" + p.name + "' has no unit normal");
        reach = std::max(reach, std::fabs(p.plane.offset));
    }
    if (!(reach > 0)) throw Error("every facet plane passes through the centre: the stone has no size");

    // The box is far larger than any sensible stone: a face of it that survives means the design is open.
    const double half = 1e4 * reach;
    const double eps = 1e-10 * half;
    Polyhedron solid = makeBox(half);
    Clipper clipper(eps);
    for (const auto& p : planes) {
        NamedPlane unit{{normalize(p.plane.normal), p.plane.offset / length(p.plane.normal)}, p.name};
        clipper.clip(solid, unit);
    }
    for (const auto& face : solid.faces)
        if (face.name == kBoxFace)
            throw Error("the facets do not close the stone: it is open toward " + [&] {
                Vec3 c;
                for (uint32_t v : face.vertices) c += solid.vertices[v];
                c = normalize(c);
                char buf[96];
                std::snprintf(buf, sizeof buf, "direction (%.2f, %.2f, %.2f)", c.x, c.y, c.z);
                return std::string(buf);
            }());

    // Keep only referenced vertices, welding close ones (a plane through an existing vertex, or a meet that is
    // exact only to the printed precision).
    PolygonMesh mesh;
    std::vector<int64_t> remap(solid.vertices.size(), -1);
    weld = std::max(weld, 1e-9 * reach);
    for (auto& face : solid.faces) {
        PolygonMesh::Polygon poly{{}, face.name};
        for (uint32_t v : face.vertices) {
            if (remap[v] < 0) {
                for (size_t j = 0; j < mesh.vertices.size() && remap[v] < 0; ++j)
                    if (length(mesh.vertices[j] - solid.vertices[v]) <= weld) remap[v] = int64_t(j);
                if (remap[v] < 0) {
                    mesh.vertices.push_back(solid.vertices[v]);
                    remap[v] = int64_t(mesh.vertices.size() - 1);
                }
            }
            const auto id = uint32_t(remap[v]);
            if (std::find(poly.vertices.begin(), poly.vertices.end(), id) == poly.vertices.end())
                poly.vertices.push_back(id);
        }
        if (poly.vertices.size() >= 3) mesh.polygons.push_back(std::move(poly));
    }
    if (mesh.polygons.size() < 4) throw Error("the facets enclose no volume");
    return mesh;
}

}  // namespace facetlight
