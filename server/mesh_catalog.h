#pragma once
// The stones a job may name: shapes shipped in the meshes folder (by file stem), shapes of the cut library
// (by snake_case name) and meshes uploaded to the service (by id). Never a path: job
// JSON is untrusted.
#include <filesystem>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "io/mesh_io.h"
#include "mesh_store.h"
#include "launcher.h"
#include "stone/stone.h"

namespace facetlight::server {

class MeshCatalog {
  public:
    MeshCatalog(MeshStore& store, std::filesystem::path meshesDir);

    // Throws Error when `mesh` names nothing we know, or its file does not build into a stone. Stones are
    // built once and kept (the last kCachedStones used): every submission naming a 15 MB upload parsed and
    // built it again on the HTTP thread (issue 18). Uploads never change under their id.
    std::shared_ptr<const Stone> resolve(const std::string& mesh) const;
    // What a child process (a launcher's job) reads the same stone from: a file path or a cut shape name.
    ChildMesh locate(const std::string& mesh) const;
    // What a sweep or a cut of `mesh` builds from (planSweepOf, cutStone): a shape of the cut library by name,
    // with its parameters, else the file of a shipped or uploaded mesh or design. Throws Error for an unknown
    // mesh.
    std::string shapeSource(const std::string& mesh) const;
    // What people call the design `mesh` names: an upload's file name, else the shape's ("round brilliant").
    std::string designName(const std::string& mesh) const;
    // {"shipped": [...], "uploaded": [...]}, each entry a stone summary with its `mesh` name.
    nlohmann::json list() const;
    // Parses and validates an upload (format from `format`, else the file name, else the content) and
    // stores it. Throws Error naming the problem.
    MeshRecord upload(std::string_view bytes, std::string_view fileName, std::optional<MeshFormat> format);
    // Forgets an uploaded mesh: its record, its file and its built stone. False when there is none.
    bool remove(const std::string& id);
    bool isUploaded(const std::string& id) const;  // an uploaded mesh's id

    static bool isShapeName(std::string_view s);  // [a-z0-9][a-z0-9_-]{0,63}

  private:
    std::optional<std::filesystem::path> shippedFile(const std::string& name) const;

    std::shared_ptr<const Stone> build(const std::string& mesh) const;
    void remember(const std::string& mesh, std::shared_ptr<const Stone> stone) const;

    static constexpr size_t kCachedStones = 16;
    MeshStore& store_;
    std::filesystem::path meshesDir_;
    mutable std::mutex mutex_;
    mutable std::optional<nlohmann::json> shippedSummaries_;  // built on first list()
    mutable std::list<std::pair<std::string, std::shared_ptr<const Stone>>> stones_;  // most recent first
};

std::string_view meshFormatName(MeshFormat format);
std::optional<MeshFormat> parseMeshFormat(std::string_view name);  // obj, stl, asc, gem

}  // namespace facetlight::server
