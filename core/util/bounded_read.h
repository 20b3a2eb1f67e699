#pragma once
// Reading a whole file named by a user, never more than a cap: `--mesh /dev/zero` read until memory ran out.
#include <cstddef>
#include <string>

namespace facetlight {

// The file's bytes. Throws Error naming the path when it cannot be opened or read, is a directory, or holds
// more than `maxBytes` (`what` says what the file was meant to be: "mesh file").
std::string readFileUpTo(const std::string& path, size_t maxBytes, const std::string& what);

}  // namespace facetlight
