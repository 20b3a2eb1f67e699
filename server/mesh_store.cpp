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

MeshStore::MeshStore(Database& db, fs::path dir, uint64_t maxBytes)
    : db_(db), dir_(std::move(dir)), maxBytes_(maxBytes) {
    std::error_code ec;
    fs::create_directories(dir_, ec);
    if (ec) throw Error("cannot create mesh directory " + dir_.string() + ": " + ec.message());
    removeTemporaryFiles(dir_);
}

void MeshStore::insertMesh(const MeshRecord& mesh, std::string_view bytes) {
    const fs::path file = meshFile(mesh);
    std::lock_guard writing(writing_);
    if (const uint64_t total = totalBytes(); total + bytes.size() > maxBytes_)
        throw MeshStoreFull("the uploaded meshes take " + std::to_string(total) + " bytes; this one's " +
                            std::to_string(bytes.size()) + " would pass the server's --max-mesh-store of " +
                            std::to_string(maxBytes_) + " bytes: delete some (DELETE /api/meshes/{id})");
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

bool MeshStore::removeMesh(const std::string& id) {
    std::lock_guard writing(writing_);
    const std::optional<MeshRecord> record = mesh(id);
    if (!record) return false;
    {
        std::lock_guard lock(db_.mutex());
        Statement s(db_.handle(), "DELETE FROM meshes WHERE id = ?");
        s.bind(1, id);
        s.step();
    }
    // The record went first: a file without one is harmless, and a crash here leaves no record without a
    // file.
    std::error_code ec;
    fs::remove(meshFile(*record), ec);
    return true;
}

uint64_t MeshStore::totalBytes() const {
    uint64_t total = 0;
    for (const MeshRecord& m : meshes()) {
        std::error_code ec;
        const uintmax_t size = fs::file_size(meshFile(m), ec);
        if (!ec) total += size;
    }
    return total;
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
