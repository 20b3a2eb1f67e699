#include "io/mesh_io.h"

#include <cctype>
#include <filesystem>

#include "io/gemcad_design.h"
#include "io/stl_format.h"
#include "util/bounded_read.h"
#include "util/error.h"

namespace facetlight {

namespace {

std::string lowercase(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = char(std::tolower(uint8_t(c)));
    return out;
}

std::string_view skipSpace(std::string_view s) {
    while (!s.empty() && std::isspace(uint8_t(s.front()))) s.remove_prefix(1);
    return s;
}

}  // namespace

std::optional<MeshFormat> formatFromFileName(std::string_view fileName) {
    const std::string ext = lowercase(std::filesystem::path(fileName).extension().string());
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".stl") return MeshFormat::Stl;
    if (ext == ".asc") return MeshFormat::GemCad;
    if (ext == ".gem") return MeshFormat::GemCadBinary;
    return std::nullopt;
}

MeshFormat detectFormat(std::string_view bytes) {
    if (isBinaryStl(bytes)) return MeshFormat::Stl;
    if (looksLikeGemCadBinary(bytes)) return MeshFormat::GemCadBinary;
    if (startsWithSolid(bytes) && lowercase(bytes.substr(0, 4096)).find("facet") != std::string::npos)
        return MeshFormat::Stl;
    if (lowercase(skipSpace(bytes).substr(0, 6)) == "gemcad") return MeshFormat::GemCad;
    return MeshFormat::Obj;
}

PolygonMesh parseGemCad(std::string_view text, const MeshLimits& limits) {
    return buildGemCadMesh(parseGemCadDesign(text, limits), limits);
}

PolygonMesh parseMesh(std::string_view bytes, MeshFormat format, const MeshLimits& limits) {
    switch (format) {
        case MeshFormat::Obj:
            return parseObj(bytes, limits);
        case MeshFormat::Stl:
            return parseStl(bytes, limits);
        case MeshFormat::GemCad:
            return parseGemCad(bytes, limits);
        case MeshFormat::GemCadBinary:
            return buildGemCadMesh(parseGemCadBinary(bytes, limits), limits);
    }
    throw Error("unknown mesh format");
}

Stone loadStone(const std::string& path, const StoneOptions& options) {
    const std::string bytes = readFileUpTo(path, options.limits.maxFileBytes, "stone file");
    const MeshFormat format = formatFromFileName(path).value_or(detectFormat(bytes));
    try {
        return Stone::build(parseMesh(bytes, format, options.limits),
                            std::filesystem::path(path).stem().string(), options);
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
}

}  // namespace facetlight
