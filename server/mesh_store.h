#pragma once
// Uploaded meshes: their records in the service's database and their files under <data>/meshes/<id>.<format>,
// each written whole (writeFileAtomically) before its record exists.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "database.h"

namespace facetlight::server {

struct MeshRecord {
    std::string id;
    std::string name;    // the file name it was uploaded as, cleaned
    std::string format;  // obj, stl or asc
    std::string createdAt;
    nlohmann::json summary;  // stoneSummaryJson of the built stone
};

class MeshStore {
  public:
    // `dir` holds the mesh files; created when missing. Temporary files a crash or a full disk left are
    // removed.
    MeshStore(Database& db, std::filesystem::path dir);

    // Throws StorageError when the file or its record cannot be written; then neither stays.
    void insertMesh(const MeshRecord& mesh, std::string_view bytes);
    std::optional<MeshRecord> mesh(const std::string& id) const;
    std::vector<MeshRecord> meshes() const;
    std::filesystem::path meshFile(const MeshRecord& mesh) const;

  private:
    Database& db_;
    std::filesystem::path dir_;
};

}  // namespace facetlight::server
