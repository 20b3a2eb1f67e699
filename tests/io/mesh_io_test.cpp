#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <map>

#include "io/mesh_io.h"
#include "support/expect_error.h"
#include "util/error.h"

using namespace facetlight;
using facetlight::test::expectError;
using facetlight::test::readFileBytes;

namespace {

const std::string kData = std::string(FACETLIGHT_SOURCE_DIR) + "/tests/data/";
const std::string kFuzzCorpus = std::string(FACETLIGHT_SOURCE_DIR) + "/tests/fuzz/corpus/";


// The unit cube's corners and its 12 outward triangles.
const Vec3 kCorners[8] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0},
                          {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, {1, 1, 1}};
const int kCubeTriangles[12][3] = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                                   {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};

void putU32(std::string& s, uint32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(char((v >> (8 * i)) & 0xff));
}
void putF32(std::string& s, float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    putU32(s, bits);
}

std::string binaryCube(const std::string& header, Vec3 corner0 = kCorners[0]) {
    std::string s = header;
    s.resize(80, '\0');
    putU32(s, 12);
    for (const auto& t : kCubeTriangles) {
        for (int i = 0; i < 3; ++i) putF32(s, 0);
        for (int c : t) {
            const Vec3 p = c == 0 ? corner0 : kCorners[c];
            putF32(s, float(p.x)), putF32(s, float(p.y)), putF32(s, float(p.z));
        }
        s += std::string(2, '\0');
    }
    return s;
}

void expectCube(const PolygonMesh& mesh, const std::string& what) {
    SCOPED_TRACE(what);
    const Stone s = Stone::build(mesh, "cube");
    EXPECT_EQ(s.facets.size(), 6u);
    EXPECT_TRUE(s.convex);
    EXPECT_NEAR(s.volume(), 1.0, 1e-12);
    EXPECT_EQ(s.vertices.size(), 8u);
}


const std::string kQuadCube =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n";

}  // namespace

TEST(ObjLoader, QuadCube) {
    const PolygonMesh m = parseObj(readFileBytes(kData + "cube_quads.obj"));
    EXPECT_EQ(m.vertices.size(), 8u);
    ASSERT_EQ(m.polygons.size(), 6u);
    for (const auto& p : m.polygons) EXPECT_EQ(p.vertices.size(), 4u);  // not triangulated
    expectCube(m, "cube_quads.obj");
}

TEST(ObjLoader, GroupObjectAndMaterialNamesWithRelativeIndices) {
    const PolygonMesh m = parseObj(readFileBytes(kData + "cube_groups.obj"));
    ASSERT_EQ(m.polygons.size(), 6u);
    const char* names[] = {"bottom", "top", "front", "back", "left", "right"};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(m.polygons[size_t(i)].name, names[i]);
    EXPECT_EQ(m.polygons[3].vertices, (std::vector<uint32_t>{2, 6, 7, 3}));  // f -6 -2 -1 -5 after 8 vertices
    const Stone s = Stone::build(m, "cube");
    ASSERT_EQ(s.facets.size(), 6u);
    std::map<std::string, int> seen;
    for (const auto& f : s.facets) ++seen[f.name];
    for (const char* n : names) EXPECT_EQ(seen[n], 1) << n;
    EXPECT_TRUE(s.convex);
}

TEST(ObjLoader, MaterialNameWinsOverGroupName) {
    const PolygonMesh m =
        parseObj("g body\nusemtl table\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ng other\nf 1 3 2\n");
    ASSERT_EQ(m.polygons.size(), 2u);
    EXPECT_EQ(m.polygons[0].name, "table");
    EXPECT_EQ(m.polygons[1].name, "table");
    const PolygonMesh g = parseObj("o gem\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    EXPECT_EQ(g.polygons[0].name, "gem");
}

TEST(ObjLoader, ForwardReferencesResolveOnceAllVerticesAreRead) {
    const PolygonMesh m = parseObj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
    ASSERT_EQ(m.polygons.size(), 1u);
    EXPECT_EQ(m.polygons[0].vertices, (std::vector<uint32_t>{0, 1, 2}));
}

TEST(ObjLoader, Errors) {
    expectError([] { parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n"); },
                "OBJ line 4: face refers to vertex 4 but the file has only 3 vertices");
    expectError([] { parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -4\n"); },
                "OBJ line 4: relative vertex index -4");
    expectError([] { parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"); }, "vertex index 0 is not valid");
    // Indices beyond an int wrapped to vertex 4 (issue 31): 2^32 + 4, 2^63 + 4, 2^64 + 4, -(2^32 - 4).
    const std::string square = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n";
    for (const char* index : {"4294967300", "9223372036854775812", "18446744073709551620", "-4294967292",
                              "4294967300/1/1", "1/4294967300", "+2147483648"})
        expectError([&] { parseObj(square + "f 2 3 " + index + "\n"); },
                    "OBJ line 5: face index '" + std::string(index) + "' is out of range");
    expectError([&] { parseObj(square + "f 2 3 " + std::string(1000, '9') + "\n"); },
                "OBJ line 5: face index '" + std::string(40, '9') + "...' is out of range");
    // The largest int is an index like any other, and leading zeros are no part of its size.
    expectError([&] { parseObj(square + "f 2 3 2147483647\n"); },
                "OBJ line 5: face refers to vertex 2147483647 but the file has only 4 vertices");
    EXPECT_EQ(parseObj(square + "f 2 3 00000000000004\n").polygons[0].vertices,
              (std::vector<uint32_t>{1, 2, 3}));
    expectError([] { parseObj("v 0 0 0\nv nan 0 0\n"); },
                "OBJ line 2: vertex coordinate 'nan' is not a finite number");
    expectError([] { parseObj("v 0 0 0\nv 1 inf 0\n"); },
                "OBJ line 2: vertex coordinate 'inf' is not a finite number");
    expectError([] { parseObj("v 0 0 1e400\n"); },
                "OBJ line 1: vertex coordinate '1e400' is not a valid number");
    expectError([] { parseObj("v 0 0 1,5\n"); }, "'1,5' is not a valid number");
    expectError([] { parseObj("v 0 0\n"); }, "OBJ line 1: a vertex needs 3 coordinates");
    expectError([] { parseObj(""); }, "the OBJ file has no faces");
    expectError([] { parseObj("# only a comment\nv 0 0 0\n"); }, "the OBJ file has no faces");
    expectError([] { parseObj("v 0 0 0\nv 1 0 0\nf 1 2\n"); },
                "OBJ line 3: a face needs at least 3 vertices, it has 2");
    expectError([] { parseObj("v 0 0 0\nf   \n"); },
                "OBJ line 2: a face needs at least 3 vertices, it has none");
    MeshLimits small;
    small.maxVertices = 7;
    expectError([&] { parseObj(kQuadCube, small); }, "too many vertices (the limit is 7)");
    small = {};
    small.maxPolygons = 5;
    expectError([&] { parseObj(kQuadCube, small); }, "too many faces (the limit is 5)");
}

TEST(ObjLoader, DegenerateFaceIsRefusedByTheStone) {
    // Three corners on a line parse, but Stone::build refuses the zero-area face.
    const PolygonMesh m = parseObj("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
    expectError([&] { Stone::build(m, "line"); }, "degenerate");
}

TEST(StlLoader, BinaryCubeIsWelded) {
    const PolygonMesh m = parseStl(binaryCube("binary cube"));
    EXPECT_EQ(m.vertices.size(), 8u);
    EXPECT_EQ(m.polygons.size(), 12u);
    expectCube(m, "binary");
}

TEST(StlLoader, BinaryWhoseHeaderBeginsWithSolid) {
    const std::string bytes = binaryCube("solid cube, and yet binary");
    EXPECT_EQ(detectFormat(bytes), MeshFormat::Stl);
    expectCube(parseStl(bytes), "binary with solid header");
}

TEST(StlLoader, AsciiCube) {
    const PolygonMesh m = parseStl(readFileBytes(kData + "cube_ascii.stl"));
    EXPECT_EQ(m.vertices.size(), 8u);
    EXPECT_EQ(m.polygons.size(), 12u);
    expectCube(m, "ascii");
}

TEST(StlLoader, NegativeZeroWeldsWithZero) {
    expectCube(parseStl(binaryCube("signed zero", {-0.0, 0.0, -0.0})), "-0");
}

TEST(StlLoader, Errors) {
    const std::string cube = binaryCube("cube");
    expectError([&] { parseStl(cube.substr(0, cube.size() - 7)); },
                "binary STL truncated: expected 684 bytes for 12 triangles, got 677");
    expectError([&] { parseStl(cube + "xx"); }, "binary STL has trailing bytes: expected 684 bytes");
    expectError([] { parseStl("short"); }, "not an STL file");
    expectError([] { parseStl(std::string(84, '\0')); }, "the STL file has no triangles");
    expectError(
        [&] {
            parseStl(binaryCube("nan", {NAN, 0, 0}));
        },
        "binary STL triangle 1 has a coordinate that is not a finite number");
    expectError([&] { parseStl(binaryCube("inf", {0, INFINITY, 0})); }, "not a finite number");
    MeshLimits small;
    small.maxPolygons = 11;
    expectError([&] { parseStl(cube, small); }, "too many triangles: 12 (the limit is 11)");
    small = {};
    small.maxVertices = 7;
    expectError([&] { parseStl(cube, small); }, "too many vertices (the limit is 7)");

    const std::string facet =
        "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n";
    expectError([] { parseStl("solid empty\nendsolid empty\n"); }, "the STL file has no triangles");
    expectError([&] { parseStl("solid x\n" + facet); },
                "expected 'facet' or 'endsolid', found the end of the file");
    expectError([] { parseStl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 nan 0\n"); },
                "ASCII STL line 4: vertex coordinate 'nan' is not a finite number");
    expectError([] { parseStl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 abc 0\n"); },
                "ASCII STL line 4: expected a number, found 'abc'");
    expectError(
        [] { parseStl("solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"); },
        "ASCII STL line 3: a facet needs at least 3 vertices, it has 2");
    expectError([] { parseStl("solid x\nfacet normal 0 0 1\nouter lop\n"); }, "expected 'loop', found 'lop'");
}

TEST(StlLoader, DegenerateTrianglesAreDroppedWithAWarning) {
    std::string ascii = readFileBytes(kData + "cube_ascii.stl");
    ascii.insert(
        ascii.find("endsolid"),
        "facet normal 0 0 0\nouter loop\nvertex 0 0 0\nvertex 0 0 0\nvertex 1 1 1\nendloop\nendfacet\n");
    const PolygonMesh m = parseStl(ascii);
    EXPECT_EQ(m.polygons.size(), 12u);
    ASSERT_EQ(m.warnings.size(), 1u);
    EXPECT_NE(m.warnings[0].find("dropped 1 degenerate"), std::string::npos);
    expectCube(m, "with a degenerate triangle");
}

TEST(GemCadLoader, BrilliantHasEveryTier) {
    const Stone s = loadStone(kData + "brilliant.asc");
    EXPECT_EQ(s.name, "brilliant");
    std::map<std::string, int> tiers;
    for (const auto& f : s.facets) tiers[f.name.substr(0, f.name.find('_'))]++;
    const std::map<std::string, int> expected = {{"T", 1},  {"C1", 8}, {"C2", 8}, {"C3", 16},
                                                 {"G", 32}, {"P1", 8}, {"P2", 16}};
    EXPECT_EQ(tiers, expected);
    EXPECT_EQ(s.facetCount(Region::Table), 1);
    EXPECT_EQ(s.facetCount(Region::Crown), 32);
    EXPECT_EQ(s.facetCount(Region::Girdle), 32);
    EXPECT_EQ(s.facetCount(Region::Pavilion), 24);
    EXPECT_TRUE(s.convex);
    EXPECT_TRUE(s.warnings.empty()) << s.warnings.front();
    ASSERT_TRUE(s.proportions.pavilionAngleDeg.has_value());
}

TEST(GemCadLoader, AzimuthConvention) {
    const Stone s = loadStone(kData + "brilliant.asc");
    std::map<std::string, const Facet*> byName;
    for (const auto& f : s.facets) byName[f.name] = &f;
    ASSERT_TRUE(byName.count("P1_1") && byName.count("G_9") && byName.count("T"));
    // P1_1 is at index 3 of 96: 11.25 degrees clockwise from +y, 41 degrees below the girdle plane.
    const Vec3 p1 = byName["P1_1"]->normal;
    EXPECT_NEAR(p1.x, std::sin(radians(41)) * std::sin(radians(11.25)), 1e-9);
    EXPECT_NEAR(p1.y, std::sin(radians(41)) * std::cos(radians(11.25)), 1e-9);
    EXPECT_NEAR(p1.z, -std::cos(radians(41)), 1e-9);
    const Vec3 g9 = byName["G_9"]->normal;  // index 24: +x
    EXPECT_NEAR(g9.x, 1, 1e-9);
    EXPECT_NEAR(byName["T"]->normal.z, 1, 1e-12);
}

TEST(GemCadLoader, CuletWrittenMinusZero) {
    const std::string design =
        "GemCad 5.0\ng 96 0\na -45 1 96 n P 24 48 72\na 45 1 96 n C 24 48 72\n"
        "a 90 1.1 96 n G 24 48 72\na -0 0.9 96 n K\na 0 0.9 n T\n";
    const PolygonMesh m = parseGemCad(design);
    const Stone s = Stone::build(m, "octahedron");
    EXPECT_EQ(s.facets.size(), 14u);
    std::map<std::string, Vec3> normals;
    for (const auto& f : s.facets) normals[f.name] = f.normal;
    EXPECT_NEAR(normals["K"].z, -1, 1e-12);
    EXPECT_NEAR(normals["T"].z, 1, 1e-12);
}

TEST(GemCadLoader, UnknownLinesAndUnreachedFacetsAreWarnings) {
    const std::string design =
        "GemCad 5.0\ng 4 0\nZ something new\na -45 1 0 1 2 3\na 45 1 0 1 2 3\n"
        "a 90 5 0 1 2 3 n far\n";
    const PolygonMesh m = parseGemCad(design);
    ASSERT_EQ(m.warnings.size(), 5u);
    EXPECT_EQ(m.warnings[0], "GemCad line 3: ignored a line of unknown kind 'Z'");
    EXPECT_EQ(m.warnings[1], "GemCad line 6: facet far_1 does not reach the stone's surface");
    const Stone s = Stone::build(m, "octahedron");
    EXPECT_EQ(s.facets.size(), 8u);
    EXPECT_EQ(s.facets[0].name.substr(0, 5), "tier1");
}

TEST(GemCadLoader, Errors) {
    const std::string head = "GemCad 5.0\ng 96 0\n";
    expectError([] { parseGemCad(""); }, "not a GemCad design");
    expectError([] { parseGemCad("g 96 0\na 0 1 0\n"); },
                "GemCad line 1: not a GemCad design: it must begin with a 'GemCad' header line");
    expectError([] { parseGemCad("GemCad 5.0\ng 0 0\n"); },
                "GemCad line 2: the gear '0' must be a whole number");
    expectError([] { parseGemCad("GemCad 5.0\na -45 1 0 24 48 72\n"); },
                "GemCad line 2: a tier comes before the gear line");
    expectError([&] { parseGemCad(head); }, "the GemCad design has no tiers");
    expectError([&] { parseGemCad(head + "a -4x5 1 0 24 48 72\n"); },
                "GemCad line 3: the angle '-4x5' is not a valid number");
    expectError([&] { parseGemCad(head + "a -45 nan 0 24 48 72\n"); },
                "the distance 'nan' is not a valid number");
    expectError([&] { parseGemCad(head + "a -45 1 0 2.4.0 48\n"); },
                "the index '2.4.0' is not a valid number");
    // An index beyond the gear wraps around it (index 120 of 96 is 24): tests/io/gemcad_design_test.cpp.
    expectError([&] { parseGemCad(head + "a -95 1 0\n"); }, "the angle must lie between -90 and 90 degrees");
    expectError([&] { parseGemCad(head + "a -45 0 0\n"); }, "the distance must be positive");
    expectError([&] { parseGemCad(head + "a -45 1 0 n\n"); }, "'n' must be followed by a name");
    expectError([&] { parseGemCad(head + "a -45 1\n"); }, "GemCad line 3: the tier lists no index");
    // A pavilion alone is open toward the top.
    expectError([&] { parseGemCad(head + "a -45 1 0 24 48 72\n"); },
                "the GemCad design does not make a stone");
    MeshLimits small;
    small.maxPolygons = 5;
    expectError([&] { parseGemCad(head + "a -45 1 0 24 48 72\na 45 1 0 24 48 72\n", small); },
                "GemCad line 4: the design has more than 5 facets");
}

// Issue 18: a tier at distance 1e300 made every facet area NaN and the stone builder dereference a null
// "largest facet" (the server died, the CLI exited 139).
TEST(GemCadLoader, HugeDistanceIsRefusedNotACrash) {
    const std::string design =
        "GemCad 5.0\ng 96 0.0\ny 1 y\nI 2.417\na -45 1e300 0 24 48 72\na 45 1 0 24 48 72\na 0 1\n";
    expectError([&] { Stone::build(parseGemCad(design), "huge"); },
                "GemCad line 5: facet 'tier1_1' lies too far");
}

// Issue 18: a rotated cube scaled 1e155 has finite coordinates whose products overflow.
TEST(ObjLoader, HugeCoordinatesAreRefusedNotACrash) {
    const std::string obj =
        readFileBytes(std::string(FACETLIGHT_SOURCE_DIR) + "/tests/fuzz/corpus/obj/cube_1e155.obj");
    ASSERT_FALSE(obj.empty());
    expectError([&] { Stone::build(parseObj(obj), "huge"); }, "vertex 1 lies too far out");
}

TEST(MeshIo, FormatFromFileName) {
    EXPECT_EQ(formatFromFileName("cut.obj"), MeshFormat::Obj);
    EXPECT_EQ(formatFromFileName("/a/b/Cut.STL"), MeshFormat::Stl);
    EXPECT_EQ(formatFromFileName("design.asc"), MeshFormat::GemCad);
    EXPECT_EQ(formatFromFileName("Design.GEM"), MeshFormat::GemCadBinary);
    EXPECT_EQ(formatFromFileName("notes.txt"), std::nullopt);
    EXPECT_EQ(formatFromFileName("obj"), std::nullopt);
    EXPECT_EQ(formatFromFileName(""), std::nullopt);
}

TEST(MeshIo, DetectFormat) {
    EXPECT_EQ(detectFormat(binaryCube("anything")), MeshFormat::Stl);
    EXPECT_EQ(detectFormat(binaryCube("solid but binary")), MeshFormat::Stl);
    EXPECT_EQ(detectFormat(readFileBytes(kData + "cube_ascii.stl")), MeshFormat::Stl);
    EXPECT_EQ(detectFormat("  SOLID x\n facet normal 0 0 1\n"), MeshFormat::Stl);
    EXPECT_EQ(detectFormat(readFileBytes(kData + "brilliant.asc")), MeshFormat::GemCad);
    const std::string gem = readFileBytes(kFuzzCorpus + "gemcad_binary/octahedron.gem");
    EXPECT_EQ(detectFormat(gem), MeshFormat::GemCadBinary);
    EXPECT_EQ(detectFormat(gem.substr(0, 20)), MeshFormat::Obj) << "too short for a facet record";
    EXPECT_EQ(detectFormat(kQuadCube), MeshFormat::Obj);
    EXPECT_EQ(detectFormat("solid-looking OBJ comment? no: v 0 0 0\n"), MeshFormat::Obj);
    EXPECT_EQ(detectFormat(""), MeshFormat::Obj);
}

TEST(MeshIo, ParseMeshDispatches) {
    EXPECT_EQ(parseMesh(kQuadCube, MeshFormat::Obj).polygons.size(), 6u);
    EXPECT_EQ(parseMesh(binaryCube("x"), MeshFormat::Stl).polygons.size(), 12u);
    EXPECT_GT(parseMesh(readFileBytes(kData + "brilliant.asc"), MeshFormat::GemCad).polygons.size(), 80u);
    EXPECT_EQ(parseMesh(readFileBytes(kFuzzCorpus + "gemcad_binary/octahedron.gem"), MeshFormat::GemCadBinary)
                  .polygons.size(),
              8u);
}

TEST(MeshIo, LoadStoneNamesThePathOnFailure) {
    expectError([] { loadStone("/nonexistent/dir/gem.obj"); }, "/nonexistent/dir/gem.obj: cannot open");
    expectError([] { loadStone(kData); }, "is a directory");
    const std::string bad = std::string(FACETLIGHT_BINARY_DIR) + "/mesh_io_test_bad.stl";
    std::ofstream(bad, std::ios::binary) << binaryCube("cut short").substr(0, 300);
    expectError([&] { loadStone(bad); }, bad + ": binary STL truncated");
}

// Issue 18: `facetlight info --mesh /dev/zero` read until memory ran out.
TEST(MeshIo, LoadStoneReadsNoMoreThanTheCap) {
    StoneOptions options;
    options.limits.maxFileBytes = 1 << 20;
    expectError([&] { loadStone("/dev/zero", options); },
                "/dev/zero: the stone file is larger than 1048576 bytes");
    options.limits.maxFileBytes = 100;
    expectError([&] { loadStone(kData + "cube_quads.obj", options); }, "is larger than 100 bytes");
}

TEST(MeshIo, LoadStoneUsesTheFileStemAsName) {
    const Stone s = loadStone(kData + "cube_quads.obj");
    EXPECT_EQ(s.name, "cube_quads");
    EXPECT_EQ(s.facets.size(), 6u);
}

TEST(MeshIo, LoadStoneReadsAGemFile) {
    const Stone s = loadStone(kFuzzCorpus + "gemcad_binary/reversed_gear.gem");
    EXPECT_EQ(s.name, "reversed_gear");
    EXPECT_EQ(s.facets.size(), 8u);  // culet, 3 pavilion, 3 crown facets and the table
}
