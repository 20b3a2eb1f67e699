#include "stone/mesh_checks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include "geometry/self_intersection.h"
#include "util/error.h"

namespace facetlight {

namespace {

constexpr size_t kMaxPolygonVertices = 4096;
// A closed surface enclosing less than this fraction of its extent cubed is flat (two-sided), not a solid.
constexpr double kMinVolumeFraction = 1e-12;

std::string formatLimit(double limit) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", limit);
    return buf;
}

std::string describeEdge(uint32_t a, uint32_t b) {
    return "between vertices " + std::to_string(a + 1) + " and " + std::to_string(b + 1);
}

// A surface that passes through itself has no inside: refuse it, naming two of the faces that cross.
void checkEmbedded(const Stone& stone, const std::vector<uint32_t>& source, double scale) {
    std::vector<TriangleIndices> corners(stone.triangles.size());
    for (size_t t = 0; t < corners.size(); ++t) corners[t] = stone.triangles[t].v;
    if (const auto crossing = findCrossingTriangles(stone.vertices, corners, 1e-9 * scale))
        throw Error("the mesh's surface passes through itself: faces " +
                    std::to_string(source[crossing->first] + 1) + " and " +
                    std::to_string(source[crossing->second] + 1) + " cross");
}

}  // namespace

double checkMeshInput(const PolygonMesh& mesh, const MeshLimits& limits) {
    if (mesh.polygons.empty()) throw Error("the mesh has no faces");
    if (mesh.vertices.size() > limits.maxVertices)
        throw Error("too many vertices: " + std::to_string(mesh.vertices.size()) + " (the limit is " +
                    std::to_string(limits.maxVertices) + ")");
    if (mesh.polygons.size() > limits.maxPolygons)
        throw Error("too many faces: " + std::to_string(mesh.polygons.size()) + " (the limit is " +
                    std::to_string(limits.maxPolygons) + ")");
    for (size_t i = 0; i < mesh.vertices.size(); ++i) {
        const Vec3& v = mesh.vertices[i];
        if (!isFinite(v))
            throw Error("vertex " + std::to_string(i + 1) + " has a coordinate that is not a finite number");
        if (std::max({std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}) > kMaxMeshCoordinate)
            throw Error("vertex " + std::to_string(i + 1) + " lies too far out: coordinates must be within " +
                        formatLimit(kMaxMeshCoordinate));
    }
    for (size_t f = 0; f < mesh.polygons.size(); ++f) {
        const auto& poly = mesh.polygons[f].vertices;
        if (poly.size() < 3)
            throw Error("face " + std::to_string(f + 1) + " has " + std::to_string(poly.size()) +
                        " vertices; a face needs at least 3");
        if (poly.size() > kMaxPolygonVertices)
            throw Error("face " + std::to_string(f + 1) + " has more than " +
                        std::to_string(kMaxPolygonVertices) + " vertices");
        for (uint32_t v : poly)
            if (v >= mesh.vertices.size())
                throw Error("face " + std::to_string(f + 1) + " refers to vertex " +
                            std::to_string(uint64_t(v) + 1) + " but there are only " +
                            std::to_string(mesh.vertices.size()));
    }
    Bounds3 b;
    for (const auto& v : mesh.vertices) b.extend(v);
    const double scale = length(b.extent());
    if (!(scale > 0)) throw Error("the mesh has no extent: all its vertices coincide");
    if (scale < kMinMeshExtent)
        throw Error("the mesh is too small: its extent must be at least " + formatLimit(kMinMeshExtent));
    return scale;
}

void checkClosedAndOrient(Stone& stone, const std::vector<uint32_t>& source, double scale) {
    const size_t nt = stone.triangles.size();
    // Undirected edge -> the triangles using it.
    std::unordered_map<detail::EdgeKey, std::vector<uint32_t>, detail::EdgeHash> uses;
    for (uint32_t t = 0; t < nt; ++t)
        for (int k = 0; k < 3; ++k) {
            uint32_t a = stone.triangles[t].v[k], b = stone.triangles[t].v[(k + 1) % 3];
            uses[{std::min(a, b), std::max(a, b)}].push_back(t);
        }
    size_t boundary = 0;
    detail::EdgeKey example{};
    for (const auto& [e, ts] : uses) {
        if (ts.size() == 1 && boundary++ == 0) example = e;
        if (ts.size() > 2)
            throw Error("the mesh is not a closed surface: the edge " + describeEdge(e.a, e.b) +
                        " is shared by " + std::to_string(ts.size()) + " faces");
    }
    if (boundary > 0)
        throw Error("the mesh is not closed: " + std::to_string(boundary) +
                    " edges border only one face (e.g. " + describeEdge(example.a, example.b) + ")");

    // Walk the surface from triangle 0: each neighbour must traverse the shared edge the other way.
    std::vector<int8_t> seen(nt, 0);
    std::vector<uint32_t> stack{0};
    seen[0] = 1;
    size_t reached = 1;
    while (!stack.empty()) {
        const uint32_t t = stack.back();
        stack.pop_back();
        for (int k = 0; k < 3; ++k) {
            uint32_t a = stone.triangles[t].v[k], b = stone.triangles[t].v[(k + 1) % 3];
            for (uint32_t o : uses[{std::min(a, b), std::max(a, b)}]) {
                if (o == t) continue;
                const auto& ov = stone.triangles[o].v;
                bool sameDirection = false;
                for (int j = 0; j < 3; ++j) sameDirection |= ov[j] == a && ov[(j + 1) % 3] == b;
                if (sameDirection)
                    throw Error("inconsistent orientation: face " + std::to_string(source[o] + 1) +
                                " is turned the other way from its neighbour face " +
                                std::to_string(source[t] + 1));
                if (!seen[o]) {
                    seen[o] = 1;
                    ++reached;
                    stack.push_back(o);
                }
            }
        }
    }
    if (reached != nt) throw Error("the mesh has several separate pieces; a stone must be one closed solid");
    const double volume = stone.volume();
    if (!(std::fabs(volume) > kMinVolumeFraction * scale * scale * scale))
        throw Error("the mesh encloses no volume: its faces lie flat against each other");
    checkEmbedded(stone, source, scale);
    if (volume < 0) {
        for (auto& t : stone.triangles) std::swap(t.v[1], t.v[2]);
        stone.warnings.push_back("all faces were oriented inward; flipped them outward");
    }
}

bool isConvex(const Stone& stone, const detail::EdgeMap& directed, double scale) {
    const double eps = 1e-7 * scale;
    for (const auto& t : stone.triangles) {
        const Facet& f = stone.facets[t.facet];
        for (int k = 0; k < 3; ++k) {
            const auto& o = stone.triangles[directed.at({t.v[(k + 1) % 3], t.v[k]})];
            for (uint32_t v : o.v)
                if (f.plane().signedDistance(stone.vertices[v]) > eps) return false;
        }
    }
    return true;
}

}  // namespace facetlight
