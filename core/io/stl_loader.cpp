// STL, binary and ASCII. STL repeats every vertex in each triangle; identical positions are welded here so
// that Stone::build sees a connected surface.
#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstring>
#include <unordered_map>

#include "io/mesh_io.h"
#include "io/stl_format.h"
#include "util/error.h"
#include "util/excerpt.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

struct BitsHash {
    size_t operator()(const std::array<uint64_t, 3>& k) const {
        uint64_t h = 0x9e3779b97f4a7c15ull;
        for (uint64_t v : k) h = (h ^ v) * 0xff51afd7ed558ccdull ^ (h >> 29);
        return size_t(h);
    }
};

// Welds exactly equal positions and drops triangles that welding made degenerate (a repeated corner); such
// a triangle's two remaining edges cancel, so dropping it keeps the surface closed.
class StlBuilder {
  public:
    explicit StlBuilder(const MeshLimits& limits) : limits_(limits) {}

    void addPolygon(const std::vector<Vec3>& corners, const std::string& where) {
        PolygonMesh::Polygon polygon;
        for (const Vec3& p : corners) {
            if (!isFinite(p)) throw Error(where + "has a coordinate that is not a finite number");
            const uint32_t id = vertexId(p);
            if (std::find(polygon.vertices.begin(), polygon.vertices.end(), id) == polygon.vertices.end())
                polygon.vertices.push_back(id);
        }
        if (polygon.vertices.size() < 3) {
            ++dropped_;
            return;
        }
        if (mesh_.polygons.size() >= limits_.maxPolygons)
            throw Error("too many triangles (the limit is " + std::to_string(limits_.maxPolygons) + ")");
        mesh_.polygons.push_back(std::move(polygon));
    }

    PolygonMesh finish() {
        if (mesh_.polygons.empty())
            throw Error(dropped_ ? "the STL file has only degenerate triangles"
                                 : "the STL file has no triangles");
        if (dropped_)
            mesh_.warnings.push_back("dropped " + std::to_string(dropped_) +
                                     " degenerate triangles (with two identical corners)");
        return std::move(mesh_);
    }

  private:
    uint32_t vertexId(const Vec3& p) {
        std::array<uint64_t, 3> key;
        const double c[3] = {p.x + 0.0, p.y + 0.0, p.z + 0.0};  // + 0.0 folds -0 into 0
        std::memcpy(key.data(), c, sizeof c);
        const auto [it, inserted] = ids_.emplace(key, uint32_t(mesh_.vertices.size()));
        if (inserted) {
            if (mesh_.vertices.size() >= limits_.maxVertices)
                throw Error("too many vertices (the limit is " + std::to_string(limits_.maxVertices) + ")");
            mesh_.vertices.push_back(p);
        }
        return it->second;
    }

    const MeshLimits& limits_;
    PolygonMesh mesh_;
    std::unordered_map<std::array<uint64_t, 3>, uint32_t, BitsHash> ids_;
    size_t dropped_ = 0;
};

uint32_t readU32(const char* p) {
    uint32_t v = 0;
    for (int i = 3; i >= 0; --i) v = (v << 8) | uint8_t(p[i]);
    return v;
}

PolygonMesh parseBinary(std::string_view bytes, const MeshLimits& limits) {
    const uint32_t count = readU32(bytes.data() + 80);
    if (count > limits.maxPolygons)
        throw Error("too many triangles: " + std::to_string(count) + " (the limit is " +
                    std::to_string(limits.maxPolygons) + ")");
    StlBuilder builder(limits);
    std::vector<Vec3> corners(3);
    for (uint32_t t = 0; t < count; ++t) {
        const char* record = bytes.data() + kStlHeaderBytes + size_t(t) * kStlTriangleBytes;
        for (int c = 0; c < 3; ++c) {
            float xyz[3];
            for (int a = 0; a < 3; ++a) xyz[a] = std::bit_cast<float>(readU32(record + 12 + 12 * c + 4 * a));
            corners[size_t(c)] = {xyz[0], xyz[1], xyz[2]};
        }
        builder.addPolygon(corners, "binary STL triangle " + std::to_string(t + 1) + " ");
    }
    return builder.finish();
}

// Whitespace-separated tokens with their line numbers.
class Lexer {
  public:
    explicit Lexer(std::string_view text) : text_(text) {}

    std::string_view next() {
        skipSpace();
        const size_t begin = pos_;
        while (pos_ < text_.size() && !isSpace(text_[pos_])) ++pos_;
        return text_.substr(begin, pos_ - begin);
    }
    void skipLine() {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    }
    bool atEnd() {
        skipSpace();
        return pos_ >= text_.size();
    }
    std::string where() const { return "ASCII STL line " + std::to_string(line_) + ": "; }

  private:
    static bool isSpace(char c) {
        return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
    }
    void skipSpace() {
        while (pos_ < text_.size() && isSpace(text_[pos_])) line_ += text_[pos_++] == '\n';
    }

    std::string_view text_;
    size_t pos_ = 0;
    size_t line_ = 1;
};

bool equalsIgnoreCase(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(x) == std::tolower(y);
           });
}

std::string quotedToken(std::string_view token) {
    return token.empty() ? "the end of the file" : inQuotes(token);
}

void expect(Lexer& lex, std::string_view keyword) {
    const std::string_view token = lex.next();
    if (!equalsIgnoreCase(token, keyword))
        throw Error(lex.where() + "expected '" + std::string(keyword) + "', found " + quotedToken(token));
}

// Normals are recomputed from the corners, so only corner coordinates must be finite.
double readNumber(Lexer& lex, bool finite) {
    const std::string_view token = lex.next();
    double value = 0;
    if (!parseNumber(token, value))
        throw Error(lex.where() + "expected a number, found " + quotedToken(token));
    if (finite && !std::isfinite(value))
        throw Error(lex.where() + "vertex coordinate " + quotedToken(token) + " is not a finite number");
    return value;
}

PolygonMesh parseAscii(std::string_view text, const MeshLimits& limits) {
    StlBuilder builder(limits);
    Lexer lex(text);
    std::vector<Vec3> corners;
    while (!lex.atEnd()) {
        expect(lex, "solid");
        lex.skipLine();  // the solid's name
        for (;;) {
            const std::string_view token = lex.next();
            if (equalsIgnoreCase(token, "endsolid")) break;
            if (!equalsIgnoreCase(token, "facet"))
                throw Error(lex.where() + "expected 'facet' or 'endsolid', found " + quotedToken(token));
            expect(lex, "normal");
            for (int a = 0; a < 3; ++a) readNumber(lex, false);
            expect(lex, "outer");
            expect(lex, "loop");
            const std::string where = lex.where();
            corners.clear();
            std::string_view next = lex.next();
            for (; equalsIgnoreCase(next, "vertex"); next = lex.next()) {
                Vec3 p;
                p.x = readNumber(lex, true);
                p.y = readNumber(lex, true);
                p.z = readNumber(lex, true);
                corners.push_back(p);
            }
            if (!equalsIgnoreCase(next, "endloop"))
                throw Error(lex.where() + "expected 'vertex' or 'endloop', found " + quotedToken(next));
            if (corners.size() < 3)
                throw Error(where + "a facet needs at least 3 vertices, it has " +
                            std::to_string(corners.size()));
            expect(lex, "endfacet");
            builder.addPolygon(corners, where + "the facet ");
        }
        lex.skipLine();  // the name repeated after endsolid
    }
    return builder.finish();
}

}  // namespace

bool isBinaryStl(std::string_view bytes) {
    return bytes.size() >= kStlHeaderBytes &&
           bytes.size() == kStlHeaderBytes + uint64_t(readU32(bytes.data() + 80)) * kStlTriangleBytes;
}

bool startsWithSolid(std::string_view bytes) {
    size_t b = 0;
    while (b < bytes.size() && std::isspace(uint8_t(bytes[b]))) ++b;
    return equalsIgnoreCase(bytes.substr(b, 5), "solid") &&
           (bytes.size() == b + 5 || std::isspace(uint8_t(bytes[b + 5])));
}

PolygonMesh parseStl(std::string_view bytes, const MeshLimits& limits) {
    if (isBinaryStl(bytes)) return parseBinary(bytes, limits);
    if (startsWithSolid(bytes)) return parseAscii(bytes, limits);
    if (bytes.size() < kStlHeaderBytes)
        throw Error("not an STL file: " + std::to_string(bytes.size()) +
                    " bytes is too short for a binary STL and it does not begin with 'solid'");
    const uint32_t count = readU32(bytes.data() + 80);
    const uint64_t expected = kStlHeaderBytes + uint64_t(count) * kStlTriangleBytes;
    throw Error(
        std::string(bytes.size() < expected ? "binary STL truncated" : "binary STL has trailing bytes") +
        ": expected " + std::to_string(expected) + " bytes for " + std::to_string(count) +
        " triangles, got " + std::to_string(bytes.size()));
}

}  // namespace facetlight
