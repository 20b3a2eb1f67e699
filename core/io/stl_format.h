#pragma once
// The shape of an STL file, shared by the STL parser and format detection.
#include <cstddef>
#include <string_view>

namespace facetlight {

constexpr size_t kStlHeaderBytes = 84;    // 80-byte header and a little-endian uint32 triangle count
constexpr size_t kStlTriangleBytes = 50;  // normal, 3 corners (float32 x 3 each) and a uint16 attribute

// Exactly 84 + 50 n bytes for the n the header announces: binary, even when the header begins with "solid".
bool isBinaryStl(std::string_view bytes);
// Begins, after white space, with the keyword "solid" (any case): ASCII STL unless isBinaryStl().
bool startsWithSolid(std::string_view bytes);

}  // namespace facetlight
