// Wavefront OBJ through tinyobjloader's callback reader: it hands over raw face indices (so we check every
// one, relative ones included) and usemtl names even when no .mtl file is at hand (uploads never have one).
// tinyobj reads a malformed or missing number as 0, so vertex lines are checked strictly first.
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "io/mesh_io.h"
#include "util/error.h"
#include "util/excerpt.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

std::string lineTag(size_t line) {
    return "OBJ line " + std::to_string(line) + ": ";
}

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

// Splits like tinyobj's safeGetline ("\n", "\r\n" or "\r" end a line) and, like tinyobj's C-string parsing,
// ignores whatever follows a NUL byte on a line.
template <typename Visit>
void forEachLine(std::string_view text, Visit&& visit) {
    size_t line = 0, pos = 0;
    while (pos < text.size()) {
        const size_t end = std::min(text.find_first_of("\r\n", pos), text.size());
        std::string_view content = text.substr(pos, end - pos);
        content = content.substr(0, content.find('\0'));
        visit(++line, content);
        pos = end + (end + 1 < text.size() && text[end] == '\r' && text[end + 1] == '\n' ? 2 : 1);
    }
}

std::string_view nextToken(std::string_view& rest) {
    size_t b = 0;
    while (b < rest.size() && isBlank(rest[b])) ++b;
    size_t e = b;
    while (e < rest.size() && !isBlank(rest[e])) ++e;
    const std::string_view token = rest.substr(b, e - b);
    rest.remove_prefix(e);
    return token;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (isBlank(s.front()) || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (isBlank(s.back()) || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// tinyobj reads a face's indices ("v", "v/vt/vn", "-2") into an int, so 4294967300, 2^64 + 4 and -4294967292
// would each wrap to vertex 4 (issue 31): an index must fit an int, read digit by digit.
void checkFaceIndices(size_t line, std::string_view token) {
    constexpr std::string_view kMax = "2147483647";
    for (std::string_view rest = token; !rest.empty();) {
        std::string_view part = rest.substr(0, rest.find('/'));
        rest.remove_prefix(std::min(rest.size(), part.size() + 1));
        if (!part.empty() && (part[0] == '-' || part[0] == '+')) part.remove_prefix(1);
        if (part.find_first_not_of("0123456789") != std::string_view::npos)
            continue;  // not a number: tinyobj's 0
        part.remove_prefix(std::min(part.find_first_not_of('0'), part.size()));
        if (part.size() > kMax.size() || (part.size() == kMax.size() && part > kMax)) {
            throw Error(lineTag(line) + "face index " + inQuotes(token) + " is out of range (at most " +
                        std::string(kMax) + " either way)");
        }
    }
}

// Vertex coordinates must be finite numbers (tinyobj would read "nan" or "1,5" as 0) and face indices fit an
// int; records each face's line for the messages of the second pass.
std::vector<size_t> checkLines(std::string_view text) {
    std::vector<size_t> faceLines;
    forEachLine(text, [&](size_t line, std::string_view content) {
        std::string_view rest = content;
        const std::string_view kind = nextToken(rest);
        if (kind == "v") {
            for (int axis = 0; axis < 3; ++axis) {
                const std::string_view token = nextToken(rest);
                if (token.empty()) throw Error(lineTag(line) + "a vertex needs 3 coordinates");
                double value = 0;
                if (!parseNumber(token, value))
                    throw Error(lineTag(line) + "vertex coordinate " + inQuotes(token) +
                                " is not a valid number");
                if (!std::isfinite(value))
                    throw Error(lineTag(line) + "vertex coordinate " + inQuotes(token) +
                                " is not a finite number");
            }
        } else if (kind == "f") {
            if (trim(rest).empty())
                throw Error(lineTag(line) + "a face needs at least 3 vertices, it has none");
            for (std::string_view token = nextToken(rest); !token.empty(); token = nextToken(rest))
                checkFaceIndices(line, token);
            faceLines.push_back(line);
        }
    });
    return faceLines;
}

struct ObjReader {
    const MeshLimits& limits;
    const std::vector<size_t>& faceLines;
    PolygonMesh mesh;
    std::string material, group;
    // Positive indices may point past the vertices read so far; they are checked once all are known.
    std::vector<std::pair<size_t, int64_t>> forwardIndices;  // (face, 0-based index)

    size_t faceLine(size_t face) const { return face < faceLines.size() ? faceLines[face] : 0; }

    void addVertex(double x, double y, double z) {
        if (mesh.vertices.size() >= limits.maxVertices)
            throw Error("too many vertices (the limit is " + std::to_string(limits.maxVertices) + ")");
        const Vec3 v{x, y, z};
        if (!isFinite(v))
            throw Error("vertex " + std::to_string(mesh.vertices.size() + 1) + " is not a finite number");
        mesh.vertices.push_back(v);
    }

    void addFace(const tinyobj::index_t* indices, int count) {
        const size_t face = mesh.polygons.size();
        const std::string where = lineTag(faceLine(face));
        if (face >= limits.maxPolygons)
            throw Error("too many faces (the limit is " + std::to_string(limits.maxPolygons) + ")");
        if (count < 3)
            throw Error(where + "a face needs at least 3 vertices, it has " + std::to_string(count));
        PolygonMesh::Polygon polygon;
        polygon.name = material.empty() ? group : material;
        polygon.vertices.reserve(size_t(count));
        const int64_t known = int64_t(mesh.vertices.size());
        for (int i = 0; i < count; ++i) {
            const int64_t raw = indices[i].vertex_index;
            if (raw == 0) throw Error(where + "vertex index 0 is not valid (OBJ counts vertices from 1)");
            const int64_t index = raw > 0 ? raw - 1 : known + raw;
            if (index < 0)
                throw Error(where + "relative vertex index " + std::to_string(raw) +
                            " reaches before the first vertex");
            if (index >= known) forwardIndices.push_back({face, index});
            polygon.vertices.push_back(uint32_t(std::min<int64_t>(index, UINT32_MAX)));
        }
        mesh.polygons.push_back(std::move(polygon));
    }

    void checkForwardIndices() const {
        for (const auto& [face, index] : forwardIndices)
            if (index >= int64_t(mesh.vertices.size()))
                throw Error(lineTag(faceLine(face)) + "face refers to vertex " + std::to_string(index + 1) +
                            " but the file has only " + std::to_string(mesh.vertices.size()) + " vertices");
    }
};

}  // namespace

PolygonMesh parseObj(std::string_view text, const MeshLimits& limits) {
    const std::vector<size_t> faceLines = checkLines(text);
    ObjReader reader{limits, faceLines, {}, {}, {}, {}};

    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = [](void* self, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
                             tinyobj::real_t) { static_cast<ObjReader*>(self)->addVertex(x, y, z); };
    callbacks.index_cb = [](void* self, tinyobj::index_t* indices, int count) {
        static_cast<ObjReader*>(self)->addFace(indices, count);
    };
    callbacks.usemtl_cb = [](void* self, const char* name, int) {
        static_cast<ObjReader*>(self)->material = std::string(trim(name));
    };
    callbacks.group_cb = [](void* self, const char** names, int count) {
        std::string joined;
        for (int i = 0; i < count; ++i) joined += (i ? " " : "") + std::string(names[i]);
        static_cast<ObjReader*>(self)->group = joined;
    };
    callbacks.object_cb = [](void* self, const char* name) {
        static_cast<ObjReader*>(self)->group = std::string(trim(name));
    };

    std::istringstream stream{std::string(text)};
    std::string warn, err;
    // No material reader: an OBJ never makes us open other files.
    tinyobj::LoadObjWithCallback(stream, callbacks, &reader, nullptr, &warn, &err);
    if (!err.empty()) throw Error("OBJ: " + std::string(trim(err)));

    reader.checkForwardIndices();
    if (reader.mesh.polygons.empty()) throw Error("the OBJ file has no faces");
    return std::move(reader.mesh);
}

}  // namespace facetlight
