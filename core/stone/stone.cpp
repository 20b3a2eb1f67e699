#include "stone/stone.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <map>
#include <numeric>
#include <unordered_map>

#include "geometry/rotation.h"
#include "geometry/self_intersection.h"
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

constexpr size_t kMaxPolygonVertices = 4096;
// A closed surface enclosing less than this fraction of its extent cubed is flat (two-sided), not a solid.
constexpr double kMinVolumeFraction = 1e-12;

std::string formatLimit(double limit) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", limit);
    return buf;
}

Vec3 newellNormal(const std::vector<Vec3>& points, const std::vector<uint32_t>& loop) {
    Vec3 n;
    for (size_t i = 0; i < loop.size(); ++i) {
        const Vec3& a = points[loop[i]];
        const Vec3& b = points[loop[(i + 1) % loop.size()]];
        n += Vec3{(a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)};
    }
    return n;  // length is twice the polygon's area
}

std::string describeEdge(uint32_t a, uint32_t b) {
    return "between vertices " + std::to_string(a + 1) + " and " + std::to_string(b + 1);
}

// Ear clipping in the polygon's own plane; ears of zero area are never cut, so vertices lying on an edge
// (shared with a neighbouring facet) stay in the mesh without creating degenerate triangles.
void triangulate(const std::vector<Vec3>& points, const std::vector<uint32_t>& loop, const Vec3& normal,
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
            const size_t a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i], c = ring[(i + 1) % ring.size()];
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
        if (!cut) throw Error("face " + std::to_string(polygonIndex + 1) + " is self-intersecting or degenerate");
    }
    if (area2(ring[0], ring[1], ring[2]) <= 2 * areaEps)
        throw Error("face " + std::to_string(polygonIndex + 1) + " is degenerate (zero area)");
    out.push_back({loop[ring[0]], loop[ring[1]], loop[ring[2]]});
}

struct EdgeKey {
    uint32_t a, b;
    bool operator==(const EdgeKey&) const = default;
};
struct EdgeHash {
    size_t operator()(const EdgeKey& e) const { return std::hash<uint64_t>()((uint64_t(e.a) << 32) | e.b); }
};

// Directed edge -> triangle; every directed edge must appear once and its reverse once.
using EdgeMap = std::unordered_map<EdgeKey, uint32_t, EdgeHash>;

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

class StoneBuilder {
public:
    StoneBuilder(const PolygonMesh& mesh, const StoneOptions& options) : mesh_(mesh), options_(options) {}

    Stone build(std::string name) {
        stone_.name = std::move(name);
        stone_.warnings = mesh_.warnings;
        validateInput();
        triangulatePolygons();
        checkClosedAndOrient();
        mergeFacets();
        if (options_.standardFrame) moveToStandardFrame();
        finishFacets();
        classifyRegions();
        measureProportions();
        stone_.convex = isConvex();
        return std::move(stone_);
    }

private:
    void validateInput() {
        if (mesh_.polygons.empty()) throw Error("the mesh has no faces");
        if (mesh_.vertices.size() > options_.limits.maxVertices)
            throw Error("too many vertices: " + std::to_string(mesh_.vertices.size()) + " (the limit is " +
                        std::to_string(options_.limits.maxVertices) + ")");
        if (mesh_.polygons.size() > options_.limits.maxPolygons)
            throw Error("too many faces: " + std::to_string(mesh_.polygons.size()) + " (the limit is " +
                        std::to_string(options_.limits.maxPolygons) + ")");
        for (size_t i = 0; i < mesh_.vertices.size(); ++i) {
            const Vec3& v = mesh_.vertices[i];
            if (!isFinite(v))
                throw Error("vertex " + std::to_string(i + 1) + " has a coordinate that is not a finite number");
            if (std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}) > kMaxMeshCoordinate)
                throw Error("vertex " + std::to_string(i + 1) + " lies too far out: coordinates must be within " +
                            formatLimit(kMaxMeshCoordinate));
        }
        for (size_t f = 0; f < mesh_.polygons.size(); ++f) {
            const auto& poly = mesh_.polygons[f].vertices;
            if (poly.size() < 3)
                throw Error("face " + std::to_string(f + 1) + " has " + std::to_string(poly.size()) +
                            " vertices; a face needs at least 3");
            if (poly.size() > kMaxPolygonVertices)
                throw Error("face " + std::to_string(f + 1) + " has more than " + std::to_string(kMaxPolygonVertices) +
                            " vertices");
            for (uint32_t v : poly)
                if (v >= mesh_.vertices.size())
                    throw Error("face " + std::to_string(f + 1) + " refers to vertex " + std::to_string(uint64_t(v) + 1) +
                                " but there are only " + std::to_string(mesh_.vertices.size()));
        }
        Bounds3 b;
        for (const auto& v : mesh_.vertices) b.extend(v);
        scale_ = length(b.extent());
        if (!(scale_ > 0)) throw Error("the mesh has no extent: all its vertices coincide");
        if (scale_ < kMinMeshExtent)
            throw Error("the mesh is too small: its extent must be at least " + formatLimit(kMinMeshExtent));
    }

    void triangulatePolygons() {
        Welded welded = weldExactDuplicates(mesh_.vertices);
        stone_.vertices = std::move(welded.vertices);
        const double areaEps = 1e-14 * scale_ * scale_;
        std::vector<std::array<uint32_t, 3>> tris;
        for (size_t f = 0; f < mesh_.polygons.size(); ++f) {
            std::vector<uint32_t> loop;
            for (uint32_t v : mesh_.polygons[f].vertices) {
                const uint32_t w = welded.remap[v];
                if (loop.empty() || loop.back() != w) loop.push_back(w);
            }
            while (loop.size() > 1 && loop.front() == loop.back()) loop.pop_back();
            const Vec3 n = newellNormal(stone_.vertices, loop);
            if (loop.size() < 3 || length(n) <= 2 * areaEps)
                throw Error("face " + std::to_string(f + 1) + " is degenerate (zero area)");
            tris.clear();
            triangulate(stone_.vertices, loop, normalize(n), areaEps, f, tris);
            for (const auto& t : tris) {
                stone_.triangles.push_back({t, 0});
                triangleSource_.push_back(uint32_t(f));
            }
        }
    }

    void checkClosedAndOrient() {
        const size_t nt = stone_.triangles.size();
        // Undirected edge -> the triangles using it.
        std::unordered_map<EdgeKey, std::vector<uint32_t>, EdgeHash> uses;
        for (uint32_t t = 0; t < nt; ++t)
            for (int k = 0; k < 3; ++k) {
                uint32_t a = stone_.triangles[t].v[k], b = stone_.triangles[t].v[(k + 1) % 3];
                uses[{std::min(a, b), std::max(a, b)}].push_back(t);
            }
        size_t boundary = 0;
        EdgeKey example{};
        for (const auto& [e, ts] : uses) {
            if (ts.size() == 1 && boundary++ == 0) example = e;
            if (ts.size() > 2)
                throw Error("the mesh is not a closed surface: the edge " + describeEdge(e.a, e.b) + " is shared by " +
                            std::to_string(ts.size()) + " faces");
        }
        if (boundary > 0)
            throw Error("the mesh is not closed: " + std::to_string(boundary) + " edges border only one face (e.g. " +
                        describeEdge(example.a, example.b) + ")");

        // Walk the surface from triangle 0: each neighbour must traverse the shared edge the other way.
        std::vector<int8_t> seen(nt, 0);
        std::vector<uint32_t> stack{0};
        seen[0] = 1;
        size_t reached = 1;
        while (!stack.empty()) {
            const uint32_t t = stack.back();
            stack.pop_back();
            for (int k = 0; k < 3; ++k) {
                uint32_t a = stone_.triangles[t].v[k], b = stone_.triangles[t].v[(k + 1) % 3];
                for (uint32_t o : uses[{std::min(a, b), std::max(a, b)}]) {
                    if (o == t) continue;
                    const auto& ov = stone_.triangles[o].v;
                    bool sameDirection = false;
                    for (int j = 0; j < 3; ++j) sameDirection |= ov[j] == a && ov[(j + 1) % 3] == b;
                    if (sameDirection)
                        throw Error("inconsistent orientation: face " + std::to_string(triangleSource_[o] + 1) +
                                    " is turned the other way from its neighbour face " +
                                    std::to_string(triangleSource_[t] + 1));
                    if (!seen[o]) {
                        seen[o] = 1;
                        ++reached;
                        stack.push_back(o);
                    }
                }
            }
        }
        if (reached != nt) throw Error("the mesh has several separate pieces; a stone must be one closed solid");
        const double volume = stone_.volume();
        if (!(std::fabs(volume) > kMinVolumeFraction * scale_ * scale_ * scale_))
            throw Error("the mesh encloses no volume: its faces lie flat against each other");
        checkEmbedded();
        if (volume < 0) {
            for (auto& t : stone_.triangles) std::swap(t.v[1], t.v[2]);
            stone_.warnings.push_back("all faces were oriented inward; flipped them outward");
        }
    }

    // A surface that passes through itself has no inside: refuse it, naming two of the faces that cross.
    void checkEmbedded() const {
        std::vector<TriangleIndices> corners(stone_.triangles.size());
        for (size_t t = 0; t < corners.size(); ++t) corners[t] = stone_.triangles[t].v;
        if (const auto crossing = findCrossingTriangles(stone_.vertices, corners, 1e-9 * scale_))
            throw Error("the mesh's surface passes through itself: faces " +
                        std::to_string(triangleSource_[crossing->first] + 1) + " and " +
                        std::to_string(triangleSource_[crossing->second] + 1) + " cross");
    }

    // Grows facets over edge-connected triangles lying in the seed triangle's plane.
    void mergeFacets() {
        const size_t nt = stone_.triangles.size();
        EdgeMap& directed = directed_;
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
                newellNormal(mesh_.vertices, mesh_.polygons[triangleSource_[seed]].vertices);
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
                    if (coplanar && dot(on, n) > 0) {
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

    std::vector<uint32_t> outlineOf(const Facet& facet, const EdgeMap& directed) const {
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
            const Vec3 newell = newellNormal(stone_.vertices, f.outline);
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

    void transform(const std::function<Vec3(const Vec3&)>& move) {
        for (auto& v : stone_.vertices) v = move(v);
    }

    // Table up: keep the file's z axis when some facet faces straight up or down (the usual case for
    // designs); otherwise turn the largest facet, taken to be the table, to face +z.
    void moveToStandardFrame() {
        auto facetNormal = [&](const Facet& f) { return normalize(newellNormal(stone_.vertices, f.outline)); };
        bool horizontal = false;
        const Facet* largest = nullptr;
        double largestArea = -1;
        for (const auto& f : stone_.facets) {
            const Vec3 n = facetNormal(f);
            horizontal |= std::fabs(n.z) > 1 - 1e-9;
            const double area = 0.5 * length(newellNormal(stone_.vertices, f.outline));
            if (area > largestArea) largestArea = area, largest = &f;
        }
        if (!largest || !(largestArea > 0)) throw Error("the mesh has no facet of positive, finite area");
        if (!horizontal) {
            const Vec3 from = facetNormal(*largest);
            const Vec3 axis = cross(from, Vec3{0, 0, 1});
            const double s = length(axis), c = from.z;
            if (s > 1e-12) {
                const Vec3 k = axis / s;
                transform([&](const Vec3& v) { return rotateAbout(v, k, c, s); });
            } else if (c < 0) {
                transform([](const Vec3& v) { return Vec3{v.x, -v.y, -v.z}; });
            }
        }
        Bounds3 b;
        for (const auto& v : stone_.vertices) b.extend(v);
        if (b.extent().y > b.extent().x * 1.001)  // the long axis along x
            transform([](const Vec3& v) { return Vec3{v.y, -v.x, v.z}; });
        b = {};
        for (const auto& v : stone_.vertices) b.extend(v);
        const GirdleBand band = girdleBand();
        const Vec3 shift{b.center().x, b.center().y, 0.5 * (band.top + band.bottom)};
        transform([&](const Vec3& v) { return v - shift; });
    }

    struct GirdleBand {
        double top = 0, bottom = 0;
    };

    static bool isGirdleNormal(const Vec3& n) { return std::fabs(n.z) < 0.02; }  // within ~1.1 deg of vertical

    // The girdle's vertical sections: above or below each corner of each girdle facet, that facet's bottom and
    // top. Each facet is a convex polygon in a vertical plane, so its height is piecewise linear along it and
    // the girdle is thinnest and thickest at such corners.
    template <class F>
    void forEachGirdleSection(F&& section) const {
        for (const auto& f : stone_.facets) {
            const Vec3 n = normalize(newellNormal(stone_.vertices, f.outline));
            if (!isGirdleNormal(n)) continue;
            const Vec3 along = normalize(cross(n, Vec3{0, 0, 1}));
            const double flat = 1e-9 * scale_;
            for (uint32_t at : f.outline) {
                const double u = dot(stone_.vertices[at], along);
                double lo = INFINITY, hi = -INFINITY;
                for (size_t i = 0; i < f.outline.size(); ++i) {
                    const Vec3& a = stone_.vertices[f.outline[i]];
                    const Vec3& b = stone_.vertices[f.outline[(i + 1) % f.outline.size()]];
                    const double ua = dot(a, along), ub = dot(b, along);
                    if (std::fabs(ub - ua) <= flat) {  // an upright edge: both its ends, if it stands here
                        if (std::fabs(u - ua) <= flat) lo = std::min({lo, a.z, b.z}), hi = std::max({hi, a.z, b.z});
                    } else if ((u - ua) * (u - ub) <= 0) {
                        const double z = a.z + (b.z - a.z) * (u - ua) / (ub - ua);
                        lo = std::min(lo, z), hi = std::max(hi, z);
                    }
                }
                if (lo <= hi) section(lo, hi);
            }
        }
    }

    // The girdle's top and bottom at its thinnest point; for a knife-edge girdle, the height of the widest
    // horizontal section.
    GirdleBand girdleBand() const {
        GirdleBand thinnest;
        double least = INFINITY;
        forEachGirdleSection([&](double lo, double hi) {
            if (hi - lo < least) least = hi - lo, thinnest = {hi, lo};
        });
        if (least < INFINITY) return thinnest;
        double bestR = -1, z = 0;
        Bounds3 b;
        for (const auto& v : stone_.vertices) b.extend(v);
        const Vec3 c = b.center();
        for (const auto& v : stone_.vertices) {
            const double r = std::hypot(v.x - c.x, v.y - c.y);
            if (r > bestR + 1e-9 * scale_) bestR = r, z = v.z;
        }
        return {z, z};
    }

    double girdleThickest() const {
        double most = 0;
        forEachGirdleSection([&](double lo, double hi) { most = std::max(most, hi - lo); });
        return most;
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

    // The vertices a facet of `region` shares with the girdle: those of the girdle facets or, on a knife edge,
    // of the other side.
    std::vector<bool> girdleVertices(Region region) const {
        std::vector<bool> atGirdle(stone_.vertices.size(), false);
        const Region otherSide = region == Region::Crown ? Region::Pavilion : Region::Crown;
        for (const auto& f : stone_.facets) {
            if (f.region != Region::Girdle && f.region != otherSide) continue;
            for (uint32_t v : f.outline) atGirdle[v] = true;
        }
        return atGirdle;
    }

    static double slopeDeg(const Facet& f) { return degrees(std::acos(std::clamp(std::fabs(f.normal.z), 0.0, 1.0))); }

    // The main facets: those that run from the table (or culet) down to the girdle; failing that, the largest
    // facet at the girdle. A facet reaches the girdle where it shares a vertex with a girdle facet (or, on a
    // knife edge, with the other side) or comes down to the girdle's thinnest point: on a fancy outline the
    // girdle's height varies, so no one height tells. Of those at the table, the largest of those that come
    // closest to the girdle (within a tenth of the crown's height: a pear's stars touch the girdle at its
    // point, but its bezels come much lower).
    const Facet* mainFacet(Region region, double girdleZ, double apexZ) const {
        const double eps = 1e-6 * scale_, side = region == Region::Crown ? 1 : -1;
        const double closeEnough = 0.1 * std::fabs(apexZ - girdleZ);
        const std::vector<bool> atGirdle = girdleVertices(region);
        const Facet* best = nullptr;
        bool bestAtApex = false;
        double bestHeight = 0;  // of the facet's lowest point above the girdle (crown; below it, pavilion)
        auto outranksBest = [&](const Facet& f, bool atApex, double height) {
            if (!best) return true;
            if (atApex != bestAtApex) return atApex;
            if (std::fabs(height - bestHeight) > closeEnough) return height < bestHeight;
            return f.area > best->area;
        };
        for (const auto& f : stone_.facets) {
            if (f.region != region) continue;
            bool touchesGirdle = false, touchesApex = false;
            double height = INFINITY;
            for (uint32_t v : f.outline) {
                const double z = stone_.vertices[v].z;
                height = std::min(height, side * (z - girdleZ));
                touchesGirdle |= atGirdle[v];
                touchesApex |= std::fabs(z - apexZ) <= eps;
            }
            if (!touchesGirdle && height > eps) continue;
            if (!outranksBest(f, touchesApex, height)) continue;
            best = &f, bestAtApex = touchesApex, bestHeight = height;
        }
        return best;
    }

    // A round brilliant's stars, upper halves and lower halves, told apart by what they touch (see
    // Proportions); nothing when the stone has no such tier.
    void measureMinorTiers(const Facet& table, double radius, double bottom) {
        Proportions& p = stone_.proportions;
        const double eps = 1e-6 * scale_;
        std::vector<bool> atTable(stone_.vertices.size(), false);
        for (uint32_t v : table.outline) atTable[v] = true;
        const std::vector<bool> crownGirdle = girdleVertices(Region::Crown);
        const std::vector<bool> pavilionGirdle = girdleVertices(Region::Pavilion);
        auto touches = [&](const Facet& f, const std::vector<bool>& set) {
            return std::any_of(f.outline.begin(), f.outline.end(), [&](uint32_t v) { return bool(set[v]); });
        };
        auto radiusOf = [&](uint32_t v) { return std::hypot(stone_.vertices[v].x, stone_.vertices[v].y); };
        struct Mean {
            double sum = 0;
            int count = 0;
            void add(double v) { sum += v, ++count; }
            std::optional<double> value() const { return count ? std::optional<double>(sum / count) : std::nullopt; }
        };
        Mean star, upper, lower, starLength, lowerLength;
        for (const auto& f : stone_.facets) {
            if (f.region == Region::Crown) {
                const bool atT = touches(f, atTable), atG = touches(f, crownGirdle);
                if (atT && !atG) {
                    star.add(slopeDeg(f));
                    // From the star's base on the table edge (its point nearest the axis) to its tip.
                    double tip = 0, base = INFINITY;
                    for (size_t i = 0; i < f.outline.size(); ++i) {
                        const Vec3& a = stone_.vertices[f.outline[i]];
                        const Vec3& b = stone_.vertices[f.outline[(i + 1) % f.outline.size()]];
                        tip = std::max(tip, std::hypot(a.x, a.y));
                        const Vec3 d{b.x - a.x, b.y - a.y, 0};
                        const double t = std::clamp(-(a.x * d.x + a.y * d.y) / std::max(dot(d, d), 1e-300), 0.0, 1.0);
                        base = std::min(base, std::hypot(a.x + t * d.x, a.y + t * d.y));
                    }
                    starLength.add(100 * (tip - base) / (radius - base));
                } else if (atG && !atT) {
                    upper.add(slopeDeg(f));
                }
            } else if (f.region == Region::Pavilion && touches(f, pavilionGirdle)) {
                const bool atApex = std::any_of(f.outline.begin(), f.outline.end(),
                                                [&](uint32_t v) { return stone_.vertices[v].z <= bottom + eps; });
                if (atApex) continue;
                lower.add(slopeDeg(f));
                double inner = INFINITY;
                for (uint32_t v : f.outline) inner = std::min(inner, radiusOf(v));
                lowerLength.add(100 * (radius - inner) / radius);
            }
        }
        if (!star.count || !upper.count || !lower.count) return;
        p.starAngleDeg = star.value(), p.upperHalfAngleDeg = upper.value(), p.lowerHalfAngleDeg = lower.value();
        p.starPct = starLength.value(), p.lowerHalfPct = lowerLength.value();
    }

    void measureProportions() {
        Proportions& p = stone_.proportions;
        const Bounds3& b = stone_.bounds;
        p.length = b.extent().x;
        p.width = b.extent().y;
        // Round: no vertex reaches much beyond the circle inscribed in the extents (a square's corners do; a
        // 16-sided girdle's reach 1 / cos 11.25 = 1.0196 times as far).
        double maxRadius = 0;
        for (const auto& v : stone_.vertices) maxRadius = std::max(maxRadius, std::hypot(v.x, v.y));
        const bool round = p.length <= p.width * 1.01 && maxRadius <= 0.25 * (p.length + p.width) * 1.025;
        p.diameter = round ? 0.5 * (p.length + p.width) : p.width;
        const double d = p.diameter;
        const GirdleBand band = girdleBand();
        const double top = b.hi.z, bottom = b.lo.z;
        p.totalDepthPct = 100 * (top - bottom) / d;
        p.girdlePct = 100 * (band.top - band.bottom) / d;
        p.girdleThickestPct = std::max(*p.girdlePct, 100 * girdleThickest() / d);
        const Facet* crownMain = stone_.facetCount(Region::Crown) > 0 ? mainFacet(Region::Crown, band.top, top) : nullptr;
        const Facet* pavilionMain =
            stone_.facetCount(Region::Pavilion) > 0 ? mainFacet(Region::Pavilion, band.bottom, bottom) : nullptr;
        double crownRim = band.top, pavilionRim = band.bottom;
        if (crownMain) {
            p.crownAngleDeg = slopeDeg(*crownMain);
            crownRim = INFINITY;
            for (uint32_t v : crownMain->outline) crownRim = std::min(crownRim, stone_.vertices[v].z);
        }
        if (pavilionMain) {
            p.pavilionAngleDeg = slopeDeg(*pavilionMain);
            pavilionRim = -INFINITY;
            for (uint32_t v : pavilionMain->outline) pavilionRim = std::max(pavilionRim, stone_.vertices[v].z);
        }
        p.crownHeightPct = 100 * (top - crownRim) / d;
        p.pavilionDepthPct = 100 * (pavilionRim - bottom) / d;
        const Facet* table = nullptr;
        for (const auto& f : stone_.facets)
            if (f.region == Region::Table) table = &f;
        if (table) {
            double maxR = 0, lo = INFINITY, hi = -INFINITY;
            for (uint32_t v : table->outline) {
                const Vec3& q = stone_.vertices[v];
                maxR = std::max(maxR, std::hypot(q.x, q.y));
                lo = std::min(lo, q.y), hi = std::max(hi, q.y);
            }
            p.tablePct = 100 * (round ? 2 * maxR : hi - lo) / d;
            if (round) measureMinorTiers(*table, d / 2, bottom);
        }
        if (p.crownHeightPct && *p.crownHeightPct <= 1e-9) p.crownHeightPct.reset(), p.crownAngleDeg.reset();
    }

    // A closed connected surface that is convex across every edge is convex (Tietze), so it is enough to
    // check each edge's far vertex against the facet plane on this side.
    bool isConvex() const {
        const double eps = 1e-7 * scale_;
        for (const auto& t : stone_.triangles) {
            const Facet& f = stone_.facets[t.facet];
            for (int k = 0; k < 3; ++k) {
                const auto& o = stone_.triangles[directed_.at({t.v[(k + 1) % 3], t.v[k]})];
                for (uint32_t v : o.v)
                    if (f.plane().signedDistance(stone_.vertices[v]) > eps) return false;
            }
        }
        return true;
    }

    const PolygonMesh& mesh_;
    const StoneOptions& options_;
    Stone stone_;
    EdgeMap directed_;
    std::vector<uint32_t> triangleSource_;  // input polygon of each triangle, for messages and names
    double scale_ = 0;
};

}  // namespace

Stone Stone::build(const PolygonMesh& mesh, std::string name, const StoneOptions& options) {
    return StoneBuilder(mesh, options).build(std::move(name));
}

}  // namespace facetlight
