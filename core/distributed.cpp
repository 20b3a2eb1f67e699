#include "distributed.h"

#include <algorithm>

namespace facetlight {

IndexRange partition(uint64_t count, int rank, int size) {
    const uint64_t parts = uint64_t(size), r = uint64_t(rank);
    const uint64_t base = count / parts, extra = count % parts;
    const uint64_t begin = r * base + std::min(r, extra);
    return {begin, begin + base + (r < extra ? 1 : 0)};
}

}  // namespace facetlight
