#include "mesh_store.h"

#include "result_store.h"
#include "util/error.h"

namespace facetlight::server {
namespace {

namespace fs = std::filesystem;

MeshRecord readMesh(const Statement& s) {
    return {s.text(0), s.text(1), s.text(2), s.text(3), nlohmann::json::parse(s.text(4))};
}

}  // namespace

MeshStore::MeshStore(Database& db, fs::path dir) : db_(db), dir_(std::move(dir)) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) throw Error("cannot create mesh directory " + dir_.string() + ": " + ec.message());
    removeTemporaryFiles(dir_);
}

void MeshStore::insertMesh(const MeshRecord& mesh, std::string_view bytes) {
    const fs::path file = meshFile(mesh);
    writeFileAtomically(file, bytes);
    try {
        std::lock_guard lock(db_.mutex());
        Statement s(db_.handle(),
                    "INSERT INTO meshes (id, name, format, created_at, summary) VALUES (?, ?, ?, ?, ?)");
        s.bind(1, mesh.id)
            .bind(2, mesh.name)
            .bind(3, mesh.format)
            .bind(4, mesh.createdAt)
            .bind(5, mesh.summary.dump());
        s.step();
    } catch (const Error&) {
        std::error_code ec;
        fs::remove(file, ec);  // no file without its record
        throw;
    }
}

std::optional<MeshRecord> MeshStore::mesh(const std::string& id) const {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(), "SELECT id, name, format, created_at, summary FROM meshes WHERE id = ?");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return readMesh(s);
}

std::vector<MeshRecord> MeshStore::meshes() const {
    std::lock_guard lock(db_.mutex());
    Statement s(db_.handle(),
                "SELECT id, name, format, created_at, summary FROM meshes ORDER BY created_at DESC");
    std::vector<MeshRecord> out;
    while (s.step()) out.push_back(readMesh(s));
    return out;
}

fs::path MeshStore::meshFile(const MeshRecord& mesh) const {
    if (!isId(mesh.id)) throw Error("invalid mesh id");
    return dir_ / (mesh.id + "." + mesh.format);
}

}  // namespace facetlight::server
