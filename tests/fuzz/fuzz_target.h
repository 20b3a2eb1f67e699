#pragma once
// What every loader fuzz target does: parse the bytes and build a Stone, with small caps so that each input
// stays fast. facetlight::Error is the expected answer to bad input; any other exception, a crash or a
// sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "io/mesh_io.h"
#include "util/error.h"

namespace facetlight::fuzz {

inline int parseAndBuild(const uint8_t* data, size_t size, MeshFormat format) {
    StoneOptions options;
    options.limits.maxVertices = 10'000;
    options.limits.maxPolygons = 10'000;
    try {
        const PolygonMesh mesh =
            parseMesh({reinterpret_cast<const char*>(data), size}, format, options.limits);
        Stone::build(mesh, "fuzz", options);
    } catch (const Error&) {
    }
    return 0;
}

}  // namespace facetlight::fuzz
