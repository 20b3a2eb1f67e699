#pragma once
// The stone's surface as directed edges: every directed edge of a closed, consistently oriented surface
// appears once and its reverse once, which is how a triangle finds its neighbour across an edge.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <unordered_map>

namespace facetlight::detail {

struct EdgeKey {
    uint32_t a, b;
    bool operator==(const EdgeKey&) const = default;
};
struct EdgeHash {
    size_t operator()(const EdgeKey& e) const { return std::hash<uint64_t>()((uint64_t(e.a) << 32) | e.b); }
};

// Directed edge -> triangle.
using EdgeMap = std::unordered_map<EdgeKey, uint32_t, EdgeHash>;

}  // namespace facetlight::detail
