#include <gtest/gtest.h>

#include <cmath>

#include "geometry/halfspace.h"
#include "stone/mesh_checks.h"
#include "stone/proportions.h"
#include "stone/stone.h"
#include "util/error.h"

using namespace facetlight;

namespace {

PolygonMesh unitCube() {
    PolygonMesh m;
    for (int i = 0; i < 8; ++i) m.vertices.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
    m.polygons = {{{0, 2, 3, 1}, "bottom"}, {{4, 5, 7, 6}, "top"}, {{0, 1, 5, 4}, "front"},
                  {{2, 6, 7, 3}, "back"},   {{0, 4, 6, 2}, "left"}, {{1, 3, 7, 5}, "right"}};
    return m;
}

PolygonMesh triangulatedCube() {
    PolygonMesh m = unitCube();
    std::vector<PolygonMesh::Polygon> tris;
    for (const auto& q : m.polygons) {
        tris.push_back({{q.vertices[0], q.vertices[1], q.vertices[2]}, ""});
        tris.push_back({{q.vertices[0], q.vertices[2], q.vertices[3]}, ""});
    }
    m.polygons = tris;
    return m;
}

void expectThrowsWith(const PolygonMesh& m, const std::string& fragment) {
    try {
        Stone::build(m, "bad");
        FAIL() << "expected an error containing '" << fragment << "'";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(Stone, CubeHasSixFacetsAndIsConvex) {
    const Stone s = Stone::build(unitCube(), "cube");
    EXPECT_EQ(s.facets.size(), 6u);
    EXPECT_EQ(s.triangles.size(), 12u);
    EXPECT_TRUE(s.convex);
    EXPECT_NEAR(s.volume(), 1.0, 1e-12);
    EXPECT_EQ(s.facetCount(Region::Table), 1);
    EXPECT_EQ(s.facetCount(Region::Girdle), 4);
    EXPECT_EQ(s.facetCount(Region::Pavilion), 1);
    for (const auto& f : s.facets) {
        EXPECT_NEAR(f.area, 1.0, 1e-12);
        EXPECT_NEAR(length(f.normal), 1.0, 1e-12);
        EXPECT_EQ(f.outline.size(), 4u);
    }
    EXPECT_NEAR(s.bounds.lo.z, -0.5, 1e-12);  // girdle plane at z = 0, centred
    EXPECT_NEAR(s.bounds.lo.x, -0.5, 1e-12);
}

TEST(Stone, TrianglesMergeIntoFacetsWithNames) {
    PolygonMesh m = triangulatedCube();
    m.polygons[2].name = "front";
    const Stone s = Stone::build(m, "cube");
    EXPECT_EQ(s.facets.size(), 6u);
    int named = 0;
    for (const auto& f : s.facets) named += f.name == "front";
    EXPECT_EQ(named, 1);
}

TEST(Stone, FlippedMeshIsFixedWithAWarning) {
    PolygonMesh m = unitCube();
    for (auto& p : m.polygons) std::reverse(p.vertices.begin(), p.vertices.end());
    const Stone s = Stone::build(m, "cube");
    EXPECT_NEAR(s.volume(), 1.0, 1e-12);
    ASSERT_EQ(s.warnings.size(), 1u);
    EXPECT_NE(s.warnings[0].find("flipped"), std::string::npos);
    for (const auto& f : s.facets) EXPECT_GT(dot(f.normal, f.centroid), 0);
}

TEST(Stone, Errors) {
    PolygonMesh open = unitCube();
    open.polygons.pop_back();
    expectThrowsWith(open, "not closed");

    PolygonMesh inconsistent = unitCube();
    std::reverse(inconsistent.polygons[0].vertices.begin(), inconsistent.polygons[0].vertices.end());
    expectThrowsWith(inconsistent, "inconsistent orientation");

    PolygonMesh nan = unitCube();
    nan.vertices[3].y = std::nan("");
    expectThrowsWith(nan, "not a finite number");

    PolygonMesh inf = unitCube();
    inf.vertices[3].y = INFINITY;
    expectThrowsWith(inf, "not a finite number");

    PolygonMesh range = unitCube();
    range.polygons[0].vertices[0] = 99;
    expectThrowsWith(range, "refers to vertex 100");

    PolygonMesh twoVertices = unitCube();
    twoVertices.polygons[0].vertices.resize(2);
    expectThrowsWith(twoVertices, "needs at least 3");

    PolygonMesh degenerate = unitCube();
    degenerate.polygons.push_back({{0, 1, 1}, ""});
    expectThrowsWith(degenerate, "degenerate");

    expectThrowsWith(PolygonMesh{}, "no faces");

    StoneOptions tight;
    tight.limits.maxVertices = 4;
    EXPECT_THROW(Stone::build(unitCube(), "cube", tight), Error);
}

PolygonMesh scaledCube(double scale) {
    PolygonMesh m = unitCube();
    for (auto& v : m.vertices) v = v * scale;
    return m;
}

// An octahedron (vertices +-x, +-y, +-z) whose +z apex is moved to `apex`.
PolygonMesh octahedronWithApex(const Vec3& apex) {
    PolygonMesh m;
    m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, apex, {0, 0, -1}};
    for (uint32_t x : {0u, 1u})
        for (uint32_t y : {2u, 3u})
            for (uint32_t z : {4u, 5u}) {
                // Outward when the corners' signs multiply to +1, reversed otherwise.
                const bool outward = ((x == 0) == (y == 2)) == (z == 4);
                m.polygons.push_back({outward ? std::vector<uint32_t>{x, y, z} : std::vector<uint32_t>{x, z, y}, ""});
            }
    return m;
}

TEST(Stone, HugeOrTinyCoordinatesAreRefused) {
    // Issue 18: coordinates of 1e155 made every area NaN and crashed moveToStandardFrame.
    expectThrowsWith(scaledCube(1e155), "lies too far out");
    expectThrowsWith(scaledCube(2e9), "coordinates must be within 1e+09");
    expectThrowsWith(scaledCube(1e-12), "too small");
    EXPECT_NEAR(Stone::build(scaledCube(1e8), "big").volume(), 1e24, 1e12);
    EXPECT_NEAR(Stone::build(scaledCube(1e-8), "small").volume(), 1e-24, 1e-36);
}

TEST(Stone, FlatTwoSidedSquareIsNotASolid) {
    PolygonMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    m.polygons = {{{0, 1, 2, 3}, "up"}, {{3, 2, 1, 0}, "down"}};
    expectThrowsWith(m, "encloses no volume");
}

TEST(Stone, SelfIntersectingOctahedronIsRefused) {
    EXPECT_TRUE(Stone::build(octahedronWithApex({0, 0, 1}), "octahedron").convex);
    // The apex pushed through the lower half: the upper faces cut through the lower ones.
    expectThrowsWith(octahedronWithApex({0.5, 0.5, -0.5}), "passes through itself");
    // The apex folded down into the girdle plane: the upper faces overlap each other flat.
    expectThrowsWith(octahedronWithApex({-2, 0, 0}), "passes through itself");
    // Pushed down but inside: a hollow, non-convex solid, which is fine.
    EXPECT_FALSE(Stone::build(octahedronWithApex({0, 0, -0.5}), "hollow").convex);
}

TEST(Stone, CollinearFirstVerticesGiveTheRightNormal) {
    // The top face starts with three collinear vertices: the midpoint of an edge is listed between its ends.
    PolygonMesh m = unitCube();
    m.vertices.push_back({0.5, 0, 1});  // vertex 8, middle of the top front edge
    m.polygons[1].vertices = {4, 8, 5, 7, 6};
    m.polygons[2].vertices = {0, 1, 5, 8, 4};
    const Stone s = Stone::build(m, "cube");
    EXPECT_EQ(s.facets.size(), 6u);
    bool foundTop = false;
    for (const auto& f : s.facets)
        if (f.normal.z > 0.999) {
            foundTop = true;
            EXPECT_NEAR(f.area, 1.0, 1e-12);
        }
    EXPECT_TRUE(foundTop);
}

TEST(Stone, NonConvexIsDetected) {
    // An L-shaped prism.
    PolygonMesh m;
    const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    for (int z = 0; z < 2; ++z)
        for (auto& p : xy) m.vertices.push_back({p[0], p[1], double(z)});
    m.polygons.push_back({{5, 4, 3, 2, 1, 0}, "bottom"});
    m.polygons.push_back({{6, 7, 8, 9, 10, 11}, "top"});
    for (uint32_t i = 0; i < 6; ++i) m.polygons.push_back({{i, (i + 1) % 6, (i + 1) % 6 + 6, i + 6}, "side"});
    const Stone s = Stone::build(m, "ell");
    EXPECT_FALSE(s.convex);
    EXPECT_EQ(s.facets.size(), 8u);
    EXPECT_NEAR(s.volume(), 3.0, 1e-12);
}

TEST(Stone, MeasuredAgainFromItsSteps) {
    // The tolerances scale with the mesh's extent, which the input check returns; measuring the built stone
    // again gives the proportions it holds.
    const PolygonMesh cube = unitCube();
    const double scale = checkMeshInput(cube, {});
    EXPECT_DOUBLE_EQ(scale, std::sqrt(3.0));
    const Stone s = Stone::build(cube, "cube");
    const Proportions again = measureProportions(s, scale);
    EXPECT_EQ(again.diameter, s.proportions.diameter);
    for (const ProportionField& field : kProportionFields)
        EXPECT_EQ(again.*field.member, s.proportions.*field.member) << field.key;
    EXPECT_NEAR(*s.proportions.tablePct, 100, 1e-9);  // the top is the table, the sides the girdle
    EXPECT_NEAR(*s.proportions.girdlePct, 100, 1e-9);
    EXPECT_FALSE(s.proportions.crownAngleDeg);
}

TEST(HalfSpace, OctahedronFromEightPlanes) {
    std::vector<NamedPlane> planes;
    for (int i = 0; i < 8; ++i) {
        const Vec3 n = normalize(Vec3{i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
        planes.push_back({{n, 1 / std::sqrt(3.0)}, "f" + std::to_string(i)});
    }
    const Stone s = Stone::build(intersectHalfSpaces(planes), "octahedron");
    EXPECT_EQ(s.facets.size(), 8u);
    EXPECT_EQ(s.vertices.size(), 6u);
    EXPECT_TRUE(s.convex);
    EXPECT_NEAR(s.volume(), 4.0 / 3.0, 1e-9);
}

TEST(HalfSpace, RefusesOpenAndEmpty) {
    std::vector<NamedPlane> open = {{{{0, 0, 1}, 1}, "a"}, {{{0, 0, -1}, 1}, "b"}, {{{1, 0, 0}, 1}, "c"},
                                    {{{-1, 0, 0}, 1}, "d"}};
    EXPECT_THROW(intersectHalfSpaces(open), Error);
    std::vector<NamedPlane> empty = open;
    empty.push_back({{{0, 1, 0}, 1}, "e"});
    empty.push_back({{{0, -1, 0}, -2}, "f"});
    EXPECT_THROW(intersectHalfSpaces(empty), Error);
}

TEST(HalfSpace, RedundantPlaneAddsNothingAndThroughVertexWelds) {
    std::vector<NamedPlane> cube;
    for (int a = 0; a < 3; ++a)
        for (int s = -1; s <= 1; s += 2) {
            Vec3 n;
            (a == 0 ? n.x : a == 1 ? n.y : n.z) = s;
            cube.push_back({{n, 1}, "c"});
        }
    cube.push_back({{{0, 0, 1}, 5}, "redundant"});
    cube.push_back({{normalize(Vec3{1, 1, 1}), std::sqrt(3.0)}, "touches_corner"});
    const Stone s = Stone::build(intersectHalfSpaces(cube), "cube");
    EXPECT_EQ(s.facets.size(), 6u);
    EXPECT_EQ(s.vertices.size(), 8u);
    EXPECT_NEAR(s.volume(), 8.0, 1e-9);
}
