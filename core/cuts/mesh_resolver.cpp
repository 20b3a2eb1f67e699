#include "cuts/mesh_resolver.h"

#include <filesystem>

#include "cuts/cut_library.h"
#include "io/mesh_io.h"
#include "util/error.h"

namespace facetlight {

Stone resolveStone(const std::string& mesh, const StoneOptions& options) {
    if (std::filesystem::exists(mesh)) return loadStone(mesh, options);
    for (const auto& shape : cutShapes())
        if (shape.name == mesh) return Stone::build(makeCut(mesh), mesh, options);
    throw Error("no such mesh file or shape: '" + mesh + "'; the shipped shapes are: " + knownShapeNames());
}

}  // namespace facetlight
