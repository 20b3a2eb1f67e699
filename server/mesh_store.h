#pragma once
// Uploaded meshes: their records in the service's database and their files under <data>/meshes/<id>.<format>,
// each written whole (writeFileAtomically) before its record exists, all of them together within a size
// (--max-mesh-store).
#include <cstdint>
#include <filesystem>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "database.h"
#include "util/error.h"

namespace facetlight::server {

struct MeshRecord {
    std::string id;
    std::string name;    // the file name it was uploaded as, cleaned
    std::string format;  // obj, stl, asc or gem
    std::string createdAt;
    nlohmann::json summary;  // stoneSummaryJson of the built stone
};

// An upload that would take the store past its size.
class MeshStoreFull : public Error {
  public:
    using Error::Error;
};

class MeshStore {
  public:
    // `dir` holds the mesh files; created when missing. Temporary files a crash or a full disk left are
    // removed. The files together may take at most `maxBytes`.
    MeshStore(Database& db, std::filesystem::path dir, uint64_t maxBytes);

    // Throws MeshStoreFull when the store would pass its size, StorageError when the file or its record
    // cannot be written; then neither stays.
    void insertMesh(const MeshRecord& mesh, std::string_view bytes);
    // Removes the mesh's record, then its file; false when there is none. Throws StorageError.
    bool removeMesh(const std::string& id);
    std::optional<MeshRecord> mesh(const std::string& id) const;
    std::vector<MeshRecord> meshes() const;
    std::filesystem::path meshFile(const MeshRecord& mesh) const;
    uint64_t totalBytes() const;  // of every mesh's file
    uint64_t maxBytes() const { return maxBytes_; }

  private:
    Database& db_;
    std::filesystem::path dir_;
    const uint64_t maxBytes_;
    std::mutex writing_;  // one insert or removal at a time: two uploads cannot both take the last space
};

}  // namespace facetlight::server
