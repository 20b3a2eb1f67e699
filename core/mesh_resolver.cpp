#include "mesh_resolver.h"

#include <filesystem>

#include "cut_library.h"
#include "error.h"
#include "mesh_io.h"

namespace facetlight {

Stone resolveStone(const std::string& mesh, const StoneOptions& options) {
    if (std::filesystem::exists(mesh)) return loadStone(mesh, options);
    for (const auto& shape : cutShapes())
        if (shape.name == mesh) return Stone::build(makeCut(mesh), mesh, options);
    throw Error("no such mesh file or shape: '" + mesh + "'; the shipped shapes are: " + knownShapeNames());
}

}  // namespace facetlight
