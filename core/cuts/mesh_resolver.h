#pragma once
// What `--mesh` (and a job's "mesh") may name: a file path, or a shipped shape of the cut library by its
// snake_case name, which stands for that shape's default design.
#include <string>

#include "stone/stone.h"

namespace facetlight {

Stone resolveStone(const std::string& mesh, const StoneOptions& options = {});

}  // namespace facetlight
