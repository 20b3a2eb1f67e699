#include "io/obj_writer.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "util/error.h"

namespace facetlight {

namespace {

void appendCoordinate(std::string& out, double v) {
    char buf[40];
    const double rounded = std::round(v * 1e9) / 1e9;
    std::snprintf(buf, sizeof buf, " %.9f", rounded == 0 ? 0.0 : rounded);  // never "-0.000000000"
    out += buf;
}

void appendHeader(std::string& out, const std::string& header) {
    std::istringstream lines(header);
    for (std::string line; std::getline(lines, line);) out += "# " + line + "\n";
}

template <class Polygons, class VertexList, class Name>
std::string write(const std::vector<Vec3>& vertices, const Polygons& polygons, VertexList vertexList,
                  Name name, const std::string& header) {
    std::string out;
    appendHeader(out, header);
    for (const Vec3& v : vertices) {
        out += "v";
        appendCoordinate(out, v.x);
        appendCoordinate(out, v.y);
        appendCoordinate(out, v.z);
        out += "\n";
    }
    for (const auto& poly : polygons) {
        out += "g " + name(poly) + "\nf";
        for (uint32_t v : vertexList(poly)) out += " " + std::to_string(v + 1);
        out += "\n";
    }
    return out;
}

}  // namespace

std::string objText(const PolygonMesh& mesh, const std::string& header) {
    return write(
        mesh.vertices, mesh.polygons, [](const PolygonMesh::Polygon& p) { return p.vertices; },
        [](const PolygonMesh::Polygon& p) { return p.name.empty() ? std::string("facet") : p.name; }, header);
}

std::string objText(const Stone& stone, const std::string& header) {
    return write(
        stone.vertices, stone.facets, [](const Facet& f) { return f.outline; },
        [](const Facet& f) { return f.name; }, header);
}

void writeTextFile(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) throw Error(path + ": cannot open for writing: " + std::strerror(errno));
    file << text;
    file.close();
    if (!file) throw Error(path + ": write failed");
}

}  // namespace facetlight
