#include "mesh_resolver.h"

#include <filesystem>

#include "error.h"
#include "mesh_io.h"

namespace facetlight {

Stone resolveStone(const std::string& mesh, const StoneOptions& options) {
    if (std::filesystem::exists(mesh)) return loadStone(mesh, options);
    throw Error("no such mesh file or shape: '" + mesh + "'");
}

}  // namespace facetlight
