#include "geometry/self_intersection.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "util/error.h"

namespace facetlight {

namespace {

// Bounds on the work: a closed surface cut into cells about one triangle wide puts a handful of triangles in
// each cell, far below these.
constexpr size_t kMaxCellEntriesPerTriangle = 64;
constexpr size_t kMaxPairTestsPerTriangle = 512;
constexpr size_t kMinPairTestBudget = 1'000'000;

// Distance of x from the line through `from` along `edge`, positive on the left seen from the side n points
// to (inside a counter-clockwise triangle).
double leftOf(const Vec3& x, const Vec3& from, const Vec3& edge, const Vec3& n) {
    return dot(cross(edge, x - from), n) / length(edge);
}

// Whether x, lying in the plane of triangle c (unit normal n), is inside it by more than eps.
bool strictlyInside(const Vec3& x, const std::array<Vec3, 3>& c, const Vec3& n, double eps) {
    for (int k = 0; k < 3; ++k)
        if (!(leftOf(x, c[k], c[(k + 1) % 3] - c[k], n) > eps)) return false;
    return true;
}

// Whether segment pq passes through the plane of triangle c (unit normal n) inside the triangle.
bool segmentCrossesTriangle(const Vec3& p, const Vec3& q, const std::array<Vec3, 3>& c, const Vec3& n,
                            double eps) {
    const double dp = dot(n, p - c[0]), dq = dot(n, q - c[0]);
    if (!((dp > eps && dq < -eps) || (dp < -eps && dq > eps))) return false;
    return strictlyInside(p + (q - p) * (dp / (dp - dq)), c, n, eps);
}

// Whether segments pq and rs, lying in one plane (unit normal n), cross each other away from their ends.
bool segmentsCross(const Vec3& p, const Vec3& q, const Vec3& r, const Vec3& s, const Vec3& n, double eps) {
    auto opposite = [&](double a, double b) { return (a > eps && b < -eps) || (a < -eps && b > eps); };
    return opposite(leftOf(r, p, q - p, n), leftOf(s, p, q - p, n)) &&
           opposite(leftOf(p, r, s - r, n), leftOf(q, r, s - r, n));
}

bool sharesVertex(const TriangleIndices& t, uint32_t v) { return t[0] == v || t[1] == v || t[2] == v; }

class OverlapTest {
  public:
    OverlapTest(const std::vector<Vec3>& vertices, const std::vector<TriangleIndices>& triangles,
                const std::vector<Vec3>& normals, double eps)
        : vertices_(vertices), triangles_(triangles), normals_(normals), eps_(eps) {}

    // Whether triangles i and j share more than the vertices and edges they have in common.
    bool operator()(uint32_t i, uint32_t j) const {
        bool coplanar = true;
        for (uint32_t v : triangles_[i]) coplanar &= std::fabs(dot(normals_[j], vertices_[v] - corner(j, 0))) <= eps_;
        if (coplanar)
            return cornerInside(i, j) || cornerInside(j, i) || edgesCross(i, j) || centreInside(i, j) ||
                   centreInside(j, i);
        return edgePierces(i, j) || edgePierces(j, i);
    }

  private:
    const Vec3& corner(uint32_t t, int k) const { return vertices_[triangles_[t][k]]; }
    std::array<Vec3, 3> corners(uint32_t t) const { return {corner(t, 0), corner(t, 1), corner(t, 2)}; }

    // An edge of s that shares no vertex with t passes through t (neighbours touch where they meet).
    bool edgePierces(uint32_t s, uint32_t t) const {
        for (int k = 0; k < 3; ++k) {
            const uint32_t p = triangles_[s][k], q = triangles_[s][(k + 1) % 3];
            if (sharesVertex(triangles_[t], p) || sharesVertex(triangles_[t], q)) continue;
            if (segmentCrossesTriangle(vertices_[p], vertices_[q], corners(t), normals_[t], eps_)) return true;
        }
        return false;
    }

    // In one plane: a corner of s that is not one of t's lies inside t.
    bool cornerInside(uint32_t s, uint32_t t) const {
        for (uint32_t v : triangles_[s])
            if (!sharesVertex(triangles_[t], v) && strictlyInside(vertices_[v], corners(t), normals_[t], eps_))
                return true;
        return false;
    }

    // In one plane: s's centroid lies inside t, as when t covers s.
    bool centreInside(uint32_t s, uint32_t t) const {
        return strictlyInside((corner(s, 0) + corner(s, 1) + corner(s, 2)) / 3.0, corners(t), normals_[t], eps_);
    }

    // In one plane: an edge of i crosses an edge of j, neither sharing a vertex with the other.
    bool edgesCross(uint32_t i, uint32_t j) const {
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) {
                const uint32_t p = triangles_[i][a], q = triangles_[i][(a + 1) % 3];
                const uint32_t r = triangles_[j][b], s = triangles_[j][(b + 1) % 3];
                if (p == r || p == s || q == r || q == s) continue;
                if (segmentsCross(vertices_[p], vertices_[q], vertices_[r], vertices_[s], normals_[j], eps_))
                    return true;
            }
        return false;
    }

    const std::vector<Vec3>& vertices_;
    const std::vector<TriangleIndices>& triangles_;
    const std::vector<Vec3>& normals_;
    double eps_;
};

struct Grid {
    Vec3 origin;
    double cell = 1;
    std::array<size_t, 3> dims{1, 1, 1};
    std::array<size_t, 3> cellOf(const Vec3& p) const {
        std::array<size_t, 3> c;
        for (int a = 0; a < 3; ++a)
            c[a] = std::min(dims[a] - 1, size_t(std::max(0.0, std::floor((p[a] - origin[a]) / cell))));
        return c;
    }
    size_t index(const std::array<size_t, 3>& c) const { return (c[2] * dims[1] + c[1]) * dims[0] + c[0]; }
};

}  // namespace

std::optional<std::pair<uint32_t, uint32_t>> findCrossingTriangles(const std::vector<Vec3>& vertices,
                                                                   const std::vector<TriangleIndices>& triangles,
                                                                   double eps) {
    const size_t n = triangles.size();
    std::vector<Bounds3> boxes(n);
    std::vector<Vec3> normals(n);
    Bounds3 all;
    double meanSize = 0;
    for (size_t i = 0; i < n; ++i) {
        for (uint32_t v : triangles[i]) boxes[i].extend(vertices[v]);
        boxes[i].lo -= Vec3{eps, eps, eps};
        boxes[i].hi += Vec3{eps, eps, eps};
        all.extend(boxes[i].lo);
        all.extend(boxes[i].hi);
        const Vec3 e = boxes[i].extent();
        meanSize += std::max({e.x, e.y, e.z}) / double(n);
        const auto& t = triangles[i];
        normals[i] = normalize(cross(vertices[t[1]] - vertices[t[0]], vertices[t[2]] - vertices[t[0]]));
    }

    // Cells about one triangle wide, coarser while the triangles would cover too many of them.
    Grid grid;
    grid.origin = all.lo;
    grid.cell = std::max(meanSize, 1e-9 * std::max({all.extent().x, all.extent().y, all.extent().z}));
    std::vector<size_t> start;
    for (;;) {
        size_t cells = 1;
        for (int a = 0; a < 3; ++a) {
            grid.dims[a] = std::max<size_t>(1, size_t(std::ceil(all.extent()[a] / grid.cell)));
            cells *= grid.dims[a];
        }
        size_t entries = 0;
        if (cells <= 4 * n + 64)
            for (size_t i = 0; i < n && entries <= kMaxCellEntriesPerTriangle * n; ++i) {
                const auto lo = grid.cellOf(boxes[i].lo), hi = grid.cellOf(boxes[i].hi);
                entries += (hi[0] - lo[0] + 1) * (hi[1] - lo[1] + 1) * (hi[2] - lo[2] + 1);
            }
        if (cells <= 4 * n + 64 && entries <= kMaxCellEntriesPerTriangle * n) {
            start.assign(cells + 1, 0);
            break;
        }
        grid.cell *= 2;
    }

    // Triangles by cell, as one array sorted by counting.
    auto forEachCell = [&](size_t i, auto&& visit) {
        const auto lo = grid.cellOf(boxes[i].lo), hi = grid.cellOf(boxes[i].hi);
        for (size_t z = lo[2]; z <= hi[2]; ++z)
            for (size_t y = lo[1]; y <= hi[1]; ++y)
                for (size_t x = lo[0]; x <= hi[0]; ++x) visit(grid.index({x, y, z}));
    };
    for (size_t i = 0; i < n; ++i) forEachCell(i, [&](size_t c) { ++start[c + 1]; });
    for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
    std::vector<uint32_t> members(start.back());
    std::vector<size_t> fill(start.begin(), start.end() - 1);
    for (size_t i = 0; i < n; ++i) forEachCell(i, [&](size_t c) { members[fill[c]++] = uint32_t(i); });

    const OverlapTest overlap(vertices, triangles, normals, eps);
    const size_t budget = std::max(kMinPairTestBudget, kMaxPairTestsPerTriangle * n);
    size_t tests = 0;
    for (size_t c = 0; c + 1 < start.size(); ++c)
        for (size_t x = start[c]; x < start[c + 1]; ++x)
            for (size_t y = x + 1; y < start[c + 1]; ++y) {
                if (++tests > budget)
                    throw Error("the mesh's triangles overlap too much to check that its surface does not cross "
                                "itself (more than " + std::to_string(budget) + " close pairs)");
                const uint32_t i = members[x], j = members[y];
                const Bounds3 &bi = boxes[i], &bj = boxes[j];
                const Vec3 lo{std::max(bi.lo.x, bj.lo.x), std::max(bi.lo.y, bj.lo.y), std::max(bi.lo.z, bj.lo.z)};
                const Vec3 hi{std::min(bi.hi.x, bj.hi.x), std::min(bi.hi.y, bj.hi.y), std::min(bi.hi.z, bj.hi.z)};
                if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) continue;
                if (grid.index(grid.cellOf(lo)) != c) continue;  // the pair is tested in its first shared cell
                if (overlap(i, j)) return std::pair{std::min(i, j), std::max(i, j)};
            }
    return std::nullopt;
}

}  // namespace facetlight
