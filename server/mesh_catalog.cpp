#include "mesh_catalog.h"

#include <algorithm>

#include "cuts/cut_library.h"
#include "stone/stone_json.h"
#include "sweep/sweep_request.h"
#include "util/error.h"
#include "util/name_table.h"

namespace facetlight::server {
namespace {

namespace fs = std::filesystem;
constexpr MeshFormat kFormats[] = {MeshFormat::Obj, MeshFormat::Stl, MeshFormat::GemCad,
                                   MeshFormat::GemCadBinary};

// The last path component of an uploaded file's name, reduced to harmless characters.
std::string cleanFileName(std::string_view fileName) {
    const size_t slash = fileName.find_last_of("/\\");
    if (slash != std::string_view::npos) fileName.remove_prefix(slash + 1);
    std::string out;
    for (char c : fileName) {
        if (out.size() >= 64) break;
        const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                        c == '_' || c == '-' || c == '.';
        out += ok ? c : '_';
    }
    while (!out.empty() && out.front() == '.') out.erase(out.begin());
    return out.empty() ? "upload" : out;
}

// A cut library shape's parameters, which a job sets in its `cut` object: the page's form is made from them.
nlohmann::json shapeParameters(const CutShape& shape) {
    nlohmann::json out = nlohmann::json::array();
    for (const CutParameter& p : shape.parameters) {
        nlohmann::json j = {
            {"name", p.name}, {"unit", p.unit}, {"help", p.help},      {"default", p.defaultValue},
            {"min", p.min},   {"max", p.max},   {"integer", p.integer}};
        if (!p.choices.empty()) j["choices"] = p.choices;
        out.push_back(std::move(j));
    }
    return out;
}

}  // namespace

std::string_view meshFormatName(MeshFormat format) {
    switch (format) {
        case MeshFormat::Obj:
            return "obj";
        case MeshFormat::Stl:
            return "stl";
        case MeshFormat::GemCad:
            return "asc";
        case MeshFormat::GemCadBinary:
            return "gem";
    }
    return "obj";
}

std::optional<MeshFormat> parseMeshFormat(std::string_view name) {
    for (MeshFormat f : kFormats) {
        if (meshFormatName(f) == name) return f;
    }
    return std::nullopt;
}

MeshCatalog::MeshCatalog(MeshStore& store, fs::path meshesDir)
    : store_(store), meshesDir_(std::move(meshesDir)) {}

bool MeshCatalog::isShapeName(std::string_view s) {
    if (s.empty() || s.size() > 64) return false;
    for (size_t i = 0; i < s.size(); ++i) {
        const char c = s[i];
        const bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || (i > 0 && (c == '_' || c == '-'));
        if (!ok) return false;
    }
    return true;
}

std::optional<fs::path> MeshCatalog::shippedFile(const std::string& name) const {
    for (MeshFormat f : kFormats) {
        const fs::path p = meshesDir_ / (name + "." + std::string(meshFormatName(f)));
        std::error_code ec;
        if (fs::is_regular_file(p, ec)) return p;
    }
    return std::nullopt;
}

std::shared_ptr<const Stone> MeshCatalog::resolve(const std::string& mesh) const {
    {
        std::lock_guard lock(mutex_);
        for (auto it = stones_.begin(); it != stones_.end(); ++it)
            if (it->first == mesh) {
                stones_.splice(stones_.begin(), stones_, it);
                return it->second;
            }
    }
    auto stone = build(mesh);  // outside the lock: building a large mesh takes seconds
    remember(mesh, stone);
    return stone;
}

void MeshCatalog::remember(const std::string& mesh, std::shared_ptr<const Stone> stone) const {
    std::lock_guard lock(mutex_);
    stones_.remove_if([&](const auto& entry) { return entry.first == mesh; });
    stones_.emplace_front(mesh, std::move(stone));
    if (stones_.size() > kCachedStones) stones_.pop_back();
}

std::shared_ptr<const Stone> MeshCatalog::build(const std::string& mesh) const {
    if (isId(mesh)) {
        const auto record = store_.mesh(mesh);
        if (!record) throw Error("mesh: no uploaded mesh with id '" + mesh + "'");
        auto stone = std::make_shared<Stone>(loadStone(store_.meshFile(*record).string()));
        stone->name = record->name;
        return stone;
    }
    if (!isShapeName(mesh)) {
        throw Error("mesh must be a shipped shape name (see GET /api/meshes) or an uploaded mesh id");
    }
    if (const auto file = shippedFile(mesh)) return std::make_shared<Stone>(loadStone(file->string()));
    for (const auto& shape : cutShapes()) {
        if (shape.name == mesh) return std::make_shared<Stone>(Stone::build(makeCut(mesh), mesh));
    }
    throw Error("mesh: unknown mesh '" + mesh + "' (see GET /api/meshes)");
}

ChildMesh MeshCatalog::locate(const std::string& mesh) const {
    if (isId(mesh)) {
        const auto record = store_.mesh(mesh);
        if (!record) throw Error("mesh: no uploaded mesh with id '" + mesh + "'");
        return {fs::absolute(store_.meshFile(*record)).string(), record->name};
    }
    if (const auto file = shippedFile(mesh)) return {fs::absolute(*file).string(), ""};
    return {mesh, mesh};
}

std::string MeshCatalog::shapeSource(const std::string& mesh) const {
    if (isLibraryShape(mesh)) return mesh;
    const ChildMesh child = locate(mesh);
    if (child.source == mesh) throw Error("mesh: unknown mesh '" + mesh + "' (see GET /api/meshes)");
    return child.source;
}

std::string MeshCatalog::designName(const std::string& mesh) const {
    if (isId(mesh)) {
        if (const auto record = store_.mesh(mesh)) return record->name;
    }
    return spacedName(mesh);
}

nlohmann::json MeshCatalog::list() const {
    std::lock_guard lock(mutex_);
    if (!shippedSummaries_) {
        nlohmann::json shipped = nlohmann::json::array();
        std::vector<std::string> names;
        std::error_code ec;
        for (const auto& entry : fs::directory_iterator(meshesDir_, ec)) {
            const std::string stem = entry.path().stem().string();
            const std::string ext = entry.path().extension().string();
            if (isShapeName(stem) && ext.size() > 1 && parseMeshFormat(ext.substr(1))) names.push_back(stem);
        }
        for (const auto& shape : cutShapes()) names.push_back(shape.name);
        std::sort(names.begin(), names.end());
        names.erase(std::unique(names.begin(), names.end()), names.end());
        for (const auto& name : names) {
            try {
                nlohmann::json j = stoneSummaryJson(*build(name));
                j["mesh"] = name;
                for (const auto& shape : cutShapes()) {
                    if (shape.name != name) continue;
                    j["description"] = shape.description;
                    j["parameters"] = shapeParameters(shape);
                }
                shipped.push_back(std::move(j));
            } catch (const Error& e) {
                shipped.push_back({{"mesh", name}, {"error", e.what()}});
            }
        }
        shippedSummaries_ = std::move(shipped);
    }
    nlohmann::json uploaded = nlohmann::json::array();
    for (const auto& m : store_.meshes()) {
        nlohmann::json j = m.summary;
        j["mesh"] = m.id;
        j["file_name"] = m.name;
        j["format"] = m.format;
        j["created_at"] = m.createdAt;
        uploaded.push_back(std::move(j));
    }
    return {{"shipped", *shippedSummaries_}, {"uploaded", std::move(uploaded)}};
}

MeshRecord MeshCatalog::upload(std::string_view bytes, std::string_view fileName,
                               std::optional<MeshFormat> format) {
    if (bytes.empty()) throw Error("the upload is empty: send the mesh file as the request body");
    const std::string name = cleanFileName(fileName);
    if (!format) format = formatFromFileName(name);
    if (!format) format = detectFormat(bytes);
    const PolygonMesh polygons = parseMesh(bytes, *format);
    const std::string stem = fs::path(name).stem().string();
    auto stone = std::make_shared<Stone>(Stone::build(polygons, stem.empty() ? "upload" : stem));
    MeshRecord record{newId(), name, std::string(meshFormatName(*format)), nowIso8601(),
                      stoneSummaryJson(*stone)};
    store_.insertMesh(record, bytes);
    stone->name = record.name;  // as resolve() names a stone read back from the store
    remember(record.id, std::move(stone));
    return record;
}

bool MeshCatalog::isUploaded(const std::string& id) const {
    return isId(id) && store_.mesh(id).has_value();
}

bool MeshCatalog::remove(const std::string& id) {
    if (!isId(id) || !store_.removeMesh(id)) return false;
    std::lock_guard lock(mutex_);
    stones_.remove_if([&](const auto& entry) { return entry.first == id; });
    return true;
}

}  // namespace facetlight::server
