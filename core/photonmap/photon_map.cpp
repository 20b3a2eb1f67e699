#include "photonmap/photon_map.h"

#include <algorithm>
#include <array>
#include <bit>

#include "util/error.h"
#include "util/parallel.h"

namespace facetlight {
namespace {

// Size of the left subtree of a complete ("left-balanced") binary tree of n >= 2 nodes: every level full but
// the last, which fills from the left.
size_t leftSubtreeSize(size_t n) {
    const int h = std::bit_width(n) - 1;       // depth of the last level
    const size_t half = size_t(1) << (h - 1);  // the left subtree's share of a full last level
    const size_t last = n - ((size_t(1) << h) - 1);
    return half - 1 + std::min(last, half);
}

int widestAxis(const Photon* begin, const Photon* end) {
    float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (const Photon* p = begin; p != end; ++p)
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], p->position[a]);
            hi[a] = std::max(hi[a], p->position[a]);
        }
    const float ext[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    return ext[0] >= ext[1] ? (ext[0] >= ext[2] ? 0 : 2) : (ext[1] >= ext[2] ? 1 : 2);
}

// Quickselect with a branch-free Lomuto partition (after A. Alexandrescu, "Speed Is Found in the Minds of
// People", CppCon 2019): the comparisons of std::nth_element's partition are coin flips to the branch
// predictor, which made the build 2 to 2.5 times slower. After too many rounds it hands over to
// std::nth_element, as an introselect would.
template <int Axis, bool OrEqual>
Photon* partitionBelow(Photon* first, Photon* last, float pivot) {
    Photon* write = first;
    for (Photon* read = first; read != last; ++read) {
        const Photon x = *read;
        *read = *write;
        *write = x;
        write += OrEqual ? !(pivot < x.position[Axis]) : x.position[Axis] < pivot;
    }
    return write;
}

template <int Axis>
void selectMedian(Photon* first, Photon* nth, Photon* last) {
    auto key = [](const Photon* p) { return p->position[Axis]; };
    int rounds = 2 * std::bit_width(size_t(last - first)) + 8;
    while (last - first > 16) {
        if (--rounds < 0) {
            std::nth_element(first, nth, last, [](const Photon& a, const Photon& b) {
                return a.position[Axis] < b.position[Axis];
            });
            return;
        }
        const float a = key(first), b = key(first + (last - first) / 2), c = key(last - 1);
        const float pivot = std::max(std::min(a, b), std::min(std::max(a, b), c));
        Photon* split = partitionBelow<Axis, false>(first, last, pivot);
        if (nth < split) {
            last = split;
            continue;
        }
        if (split == first) {  // the pivot is the least key: split off its copies, or it never progresses
            split = partitionBelow<Axis, true>(first, last, pivot);
            if (nth < split) return;
        }
        first = split;
    }
    for (Photon* i = first + 1; i < last; ++i) {
        const Photon x = *i;
        Photon* j = i;
        for (; j > first && x.position[Axis] < key(j - 1); --j) *j = *(j - 1);
        *j = x;
    }
}

// scratch[0, n) to be placed as the subtree rooted at heap node `node`.
struct Subtree {
    Photon* scratch;
    size_t n;
    size_t node;
};

// Places the subtree's root (its median on the widest axis) and returns what is left of it: the left and the
// right subtree, permuted in place. Subtrees are disjoint, so any worker may place any of them.
std::array<Subtree, 2> placeRoot(const Subtree& t, Photon* heap) {
    if (t.n == 1) {
        heap[t.node] = t.scratch[0];
        heap[t.node].setAxis(0);  // a leaf: no split plane
        return {Subtree{t.scratch, 0, 0}, Subtree{t.scratch, 0, 0}};
    }
    const int axis = widestAxis(t.scratch, t.scratch + t.n);
    const size_t m = leftSubtreeSize(t.n);
    Photon* median = t.scratch + m;
    if (axis == 0) selectMedian<0>(t.scratch, median, t.scratch + t.n);
    if (axis == 1) selectMedian<1>(t.scratch, median, t.scratch + t.n);
    if (axis == 2) selectMedian<2>(t.scratch, median, t.scratch + t.n);
    heap[t.node] = *median;
    heap[t.node].setAxis(axis);
    return {Subtree{t.scratch, m, 2 * t.node + 1}, Subtree{median + 1, t.n - m - 1, 2 * t.node + 2}};
}

// The whole subtree, on this thread.
void build(Subtree t, Photon* heap) {
    while (t.n > 0) {
        const auto [left, right] = placeRoot(t, heap);
        if (right.n > 0) build(right, heap);
        t = left;
    }
}

// Replaces the top (largest) of a max-heap by a smaller x: one sift down where pop_heap + push_heap take
// two passes (5 to 60% more gathers per second in bench/photon_map_bench).
inline void replaceTop(Neighbor* heap, uint32_t k, Neighbor x) {
    uint32_t i = 0;
    for (;;) {
        uint32_t c = 2 * i + 1;
        if (c >= k) break;
        if (c + 1 < k && heap[c].distance2 < heap[c + 1].distance2) ++c;
        if (!(x.distance2 < heap[c].distance2)) break;
        heap[i] = heap[c];
        i = c;
    }
    heap[i] = x;
}

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, int threads) {
    if (photons.size() >= UINT32_MAX / 2) throw Error("too many photons for one photon map");
    for (const Photon& p : photons)
        if (!std::isfinite(p.position[0]) || !std::isfinite(p.position[1]) || !std::isfinite(p.position[2]))
            throw Error("photon map: a photon has a non-finite position");
    photons_.resize(photons.size());
    // The top levels one level at a time, each level's roots placed in parallel, until there is a subtree for
    // every thread; then the subtrees whole, in parallel.
    Photon* heap = photons_.data();
    std::vector<Subtree> level;
    if (!photons.empty()) level.push_back({photons.data(), photons.size(), 0});
    while (!level.empty() && level.size() < size_t(std::max(threads, 1))) {
        std::vector<std::array<Subtree, 2>> split(level.size());
        parallelForBlocks(BlockLoop{0, level.size(), 1, threads}, nullptr, [&](int, uint64_t i, uint64_t) {
            split[i] = placeRoot(level[i], heap);
            return uint64_t(0);
        });
        level.clear();
        for (const auto& pair : split)
            for (const Subtree& t : pair)
                if (t.n > 0) level.push_back(t);
    }
    parallelForBlocks(BlockLoop{0, level.size(), 1, threads}, nullptr, [&](int, uint64_t i, uint64_t) {
        build(level[i], heap);
        return uint64_t(0);
    });
}

uint32_t PhotonMap::nearest(const float q[3], Neighbor* heap, uint32_t k, float& bound2,
                            uint64_t& visited) const {
    const uint32_t n = uint32_t(photons_.size());
    if (n == 0 || k == 0) return 0;
    const Photon* photons = photons_.data();
    struct Pending {
        uint32_t node;
        float plane2;  // squared distance from q to the plane that separates it from the node
    };
    Pending stack[64];  // one entry per level at most, and a uint32_t tree has fewer than 32
    int top = 0;
    uint32_t found = 0;
    uint32_t count = 0;
    float r2 = bound2;  // a local: stores to the heap could alias a reference
    uint32_t node = 0;
    for (;;) {
        for (;;) {
            const uint32_t left = 2 * node + 1;
            // The lower levels miss the cache: fetch the children while this node is tested.
            if (left < n) __builtin_prefetch(photons + left);
            const Photon& p = photons[node];
            ++count;
            const float dx = q[0] - p.position[0], dy = q[1] - p.position[1], dz = q[2] - p.position[2];
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (d2 < r2) {
                if (found < k) {
                    heap[found++] = {d2, node};
                    std::push_heap(heap, heap + found);
                    if (found == k) r2 = heap[0].distance2;
                } else {
                    replaceTop(heap, k, {d2, node});
                    r2 = heap[0].distance2;
                }
            }
            if (left >= n) break;
            const int axis = p.axis();
            const float d = q[axis] - p.position[axis];
            const uint32_t nearChild = d < 0 ? left : left + 1;
            const uint32_t farChild = d < 0 ? left + 1 : left;
            if (farChild < n && d * d < r2) stack[top++] = {farChild, d * d};
            if (nearChild >= n) break;
            node = nearChild;
        }
        do {
            if (top == 0) {
                visited += count;
                bound2 = r2;
                return found;
            }
        } while (stack[--top].plane2 >= r2);
        node = stack[top].node;
    }
}

GatherResult PhotonMap::gather(const Vec3& p, std::span<Neighbor> buffer, GatherState& state,
                               const GatherSettings& settings) const {
    const float q[3] = {float(p.x), float(p.y), float(p.z)};
    const uint32_t k = uint32_t(std::min<size_t>(buffer.size(), UINT32_MAX));
    const float max2 = settings.maxRadius * settings.maxRadius;
    ++state.queries;
    if (settings.cachedRadius && state.lastRadius2 > 0) {
        float r2 = std::min(max2, state.lastRadius2 * settings.cacheGrowth * settings.cacheGrowth);
        const bool bounded = r2 < max2;
        const uint32_t found = nearest(q, buffer.data(), k, r2, state.nodesVisited);
        if (found == k) {
            state.lastRadius2 = r2;
            return {buffer.first(found), r2};
        }
        if (!bounded) return {buffer.first(found), max2};
        ++state.retries;
    }
    float r2 = max2;
    const uint32_t found = nearest(q, buffer.data(), k, r2, state.nodesVisited);
    if (found == k && k > 0) state.lastRadius2 = r2;
    if (found == k || std::isfinite(max2)) return {buffer.first(found), r2};
    return {buffer.first(found), found > 0 ? buffer[0].distance2 : 0.0f};
}

double PhotonMap::irradiance(const Vec3& p, const Vec3& normal, std::span<Neighbor> buffer,
                             GatherState& state, const GatherSettings& settings) const {
    return estimate<double>(p, buffer, state, settings, [&](const Photon& ph) {
        return dot(ph.travel(), normal) < 0 ? double(ph.power) : 0.0;
    });
}

}  // namespace facetlight
