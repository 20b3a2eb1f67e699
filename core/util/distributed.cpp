#include "util/distributed.h"

#include <algorithm>

namespace facetlight {

bool anyRank(Communicator& comm, bool flag) {
    if (comm.size() == 1) return flag;
    uint64_t count = flag ? 1 : 0;
    comm.sumToRoot(std::span<uint64_t>(&count, 1));
    std::string answer(1, comm.isRoot() && count > 0 ? '1' : '0');
    comm.broadcast(answer);
    return answer == "1";
}

IndexRange partition(uint64_t count, int rank, int size) {
    const uint64_t parts = uint64_t(size), r = uint64_t(rank);
    const uint64_t base = count / parts, extra = count % parts;
    const uint64_t begin = r * base + std::min(r, extra);
    return {begin, begin + base + (r < extra ? 1 : 0)};
}

}  // namespace facetlight
