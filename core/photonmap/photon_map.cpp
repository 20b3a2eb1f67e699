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

// What the build moves while it selects medians: a photon's position and, in the fourth lane, the bits of its
// index in the input; 16 aligned bytes where a Photon takes 20 unaligned ones. A vector type (GCC and Clang)
// so that every copy is one load and one store: copied field by field, the compiler's narrow stores stalled
// the next wide load of the same item (store forwarding) and the build ran 2x slower. The selection sees only
// the positions, so it permutes these exactly as it would the photons.
typedef float Item __attribute__((vector_size(16)));

uint32_t inputIndex(const Item& item) {
    return std::bit_cast<uint32_t>(item[3]);
}

// The axis of the largest extent. Two boxes side by side: one min and one max a photon, each waiting for
// the last, left the loop bound by their latency.
int widestAxis(const Item* begin, const Item* end) {
    Item lo0 = {INFINITY, INFINITY, INFINITY, INFINITY}, hi0 = -lo0, lo1 = lo0, hi1 = hi0;
    const Item* p = begin;
    for (; end - p >= 2; p += 2) {
        lo0 = p[0] < lo0 ? p[0] : lo0;
        hi0 = hi0 < p[0] ? p[0] : hi0;
        lo1 = p[1] < lo1 ? p[1] : lo1;
        hi1 = hi1 < p[1] ? p[1] : hi1;
    }
    if (p != end) {
        lo0 = *p < lo0 ? *p : lo0;
        hi0 = hi0 < *p ? *p : hi0;
    }
    const Item lo = lo1 < lo0 ? lo1 : lo0, hi = hi0 < hi1 ? hi1 : hi0;
    const Item ext = hi - lo;  // lane 3 (index bits) unused
    return ext[0] >= ext[1] ? (ext[0] >= ext[2] ? 0 : 2) : (ext[1] >= ext[2] ? 1 : 2);
}

// Quickselect with a branch-free Lomuto partition (after A. Alexandrescu, "Speed Is Found in the Minds of
// People", CppCon 2019): the comparisons of std::nth_element's partition are coin flips to the branch
// predictor, which made the build 2 to 2.5 times slower. After too many rounds it hands over to
// std::nth_element, as an introselect would.
template <int Axis, bool OrEqual>
Item* partitionBelow(Item* first, Item* last, float pivot) {
    Item* write = first;
    for (Item* read = first; read != last; ++read) {
        const Item x = *read;
        *read = *write;
        *write = x;
        write += OrEqual ? !(pivot < x[Axis]) : x[Axis] < pivot;
    }
    return write;
}

template <int Axis>
void selectMedian(Item* first, Item* nth, Item* last) {
    auto key = [](const Item* p) { return (*p)[Axis]; };
    int rounds = 2 * std::bit_width(size_t(last - first)) + 8;
    while (last - first > 16) {
        if (--rounds < 0) {
            std::nth_element(first, nth, last,
                             [](const Item& a, const Item& b) { return a[Axis] < b[Axis]; });
            return;
        }
        const float a = key(first), b = key(first + (last - first) / 2), c = key(last - 1);
        const float pivot = std::max(std::min(a, b), std::min(std::max(a, b), c));
        Item* split = partitionBelow<Axis, false>(first, last, pivot);
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
    for (Item* i = first + 1; i < last; ++i) {
        const Item x = *i;
        Item* j = i;
        for (; j > first && x[Axis] < key(j - 1); --j) *j = *(j - 1);
        *j = x;
    }
}

// items[0, n) to be placed as the subtree rooted at heap node `node`.
struct Subtree {
    Item* items;
    size_t n;
    size_t node;
};

// Where the build puts the tree: the input index and split axis of every heap node; the photons are copied
// into heap order once, at the end.
struct Placement {
    uint32_t* index;
    uint8_t* axis;
};

// Places the subtree's root (its median on the widest axis) and returns what is left of it: the left and the
// right subtree, permuted in place. Subtrees are disjoint, so any worker may place any of them.
std::array<Subtree, 2> placeRoot(const Subtree& t, const Placement& out) {
    if (t.n == 1) {
        out.index[t.node] = inputIndex(t.items[0]);
        out.axis[t.node] = 0;  // a leaf: no split plane
        return {Subtree{t.items, 0, 0}, Subtree{t.items, 0, 0}};
    }
    const int axis = widestAxis(t.items, t.items + t.n);
    const size_t m = leftSubtreeSize(t.n);
    Item* median = t.items + m;
    if (axis == 0) selectMedian<0>(t.items, median, t.items + t.n);
    if (axis == 1) selectMedian<1>(t.items, median, t.items + t.n);
    if (axis == 2) selectMedian<2>(t.items, median, t.items + t.n);
    out.index[t.node] = inputIndex(*median);
    out.axis[t.node] = uint8_t(axis);
    return {Subtree{t.items, m, 2 * t.node + 1}, Subtree{median + 1, t.n - m - 1, 2 * t.node + 2}};
}

// The whole subtree, on this thread.
void build(Subtree t, const Placement& out) {
    while (t.n > 0) {
        const auto [left, right] = placeRoot(t, out);
        if (right.n > 0) build(right, out);
        t = left;
    }
}

// The gather's walk tests the subtrees of the tree's last kBucketLevels levels whole (15 photons, in 4 runs
// of consecutive nodes): 1.2x the gathers per CPU second of a walk to the leaves in raster order, though it
// tests 1.2x the photons (bench/photon_map_bench, 3 levels 1.15x, 5 levels faster in raster order but
// slower in random order).
constexpr int kBucketLevels = 4;

// A photon's place in the order of the gather: its squared distance, then its index, in one unsigned word (a
// non-negative float's bits order as the float does). Every key is distinct, so the k nearest are one set
// whatever the walk.
uint64_t key(float d2, uint32_t node) {
    return uint64_t(std::bit_cast<uint32_t>(d2)) << 32 | node;
}

float keyDistance2(uint64_t key) {
    return std::bit_cast<float>(uint32_t(key >> 32));
}

// The least squared bound that lets a photon at the key's distance through (the walk keeps d2 < bound).
float boundPast(uint64_t key) {
    return std::bit_cast<float>(uint32_t(key >> 32) + 1);
}

// Replaces the top (largest) of a max-heap by a smaller x: one sift down where pop_heap + push_heap take
// two passes (5 to 60% more gathers per second in bench/photon_map_bench). The larger child is picked by
// arithmetic, not a branch: which sibling is larger is a coin flip to the branch predictor.
inline void replaceTop(uint64_t* heap, uint32_t k, uint64_t x) {
    uint32_t i = 0, c = 1;
    for (; c + 1 < k; c = 2 * c + 1) {
        c += heap[c] < heap[c + 1];
        if (!(x < heap[c])) {
            heap[i] = x;
            return;
        }
        heap[i] = heap[c];
        i = c;
    }
    if (c < k && x < heap[c]) {  // a last parent with one child
        heap[i] = heap[c];
        i = c;
    }
    heap[i] = x;
}

// The n-th smallest (from 0) of distinct keys, permuting them: quickselect with the build's branch-free
// partition (the comparisons are coin flips to the branch predictor). With distinct keys the median of three
// has a smaller and a larger key beside it, so every round shrinks the range.
uint64_t selectKey(uint64_t* first, uint64_t* last, uint64_t* nth) {
    int rounds = 2 * std::bit_width(size_t(last - first)) + 8;
    while (last - first > 16) {
        if (--rounds < 0) {
            std::nth_element(first, nth, last);
            return *nth;
        }
        const uint64_t a = *first, b = first[(last - first) / 2], c = last[-1];
        const uint64_t pivot = std::max(std::min(a, b), std::min(std::max(a, b), c));
        uint64_t* write = first;
        for (uint64_t* read = first; read != last; ++read) {
            const uint64_t x = *read;
            *read = *write;
            *write = x;
            write += x < pivot;
        }
        if (nth < write)
            last = write;
        else
            first = write;
    }
    std::sort(first, last);
    return *nth;
}

}  // namespace

PhotonMap::PhotonMap(std::vector<Photon> photons, int threads) {
    if (photons.size() >= UINT32_MAX / 2) throw Error("too many photons for one photon map");
    const size_t n = photons.size();
    if (n == 0) return;
    const int workers = std::max(threads, 1);
    constexpr uint64_t kBlock = 1 << 16;
    std::vector<Item> items(n);
    parallelForBlocks(BlockLoop{0, n, kBlock, workers}, nullptr, [&](int, uint64_t first, uint64_t last) {
        for (uint64_t i = first; i < last; ++i) {
            const float* p = photons[i].position;
            if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
                throw Error("photon map: a photon has a non-finite position");
            items[i] = Item{p[0], p[1], p[2], std::bit_cast<float>(uint32_t(i))};
        }
        return uint64_t(0);
    });
    std::vector<uint32_t> index(n);
    std::vector<uint8_t> axis(n);
    const Placement out{index.data(), axis.data()};
    // The top levels one level at a time, each level's roots placed in parallel, until there is a subtree for
    // every thread; then the subtrees whole, in parallel.
    std::vector<Subtree> level{{items.data(), n, 0}};
    while (!level.empty() && level.size() < size_t(workers)) {
        std::vector<std::array<Subtree, 2>> split(level.size());
        parallelForBlocks(BlockLoop{0, level.size(), 1, workers}, nullptr, [&](int, uint64_t i, uint64_t) {
            split[i] = placeRoot(level[i], out);
            return uint64_t(0);
        });
        level.clear();
        for (const auto& pair : split)
            for (const Subtree& t : pair)
                if (t.n > 0) level.push_back(t);
    }
    parallelForBlocks(BlockLoop{0, level.size(), 1, workers}, nullptr, [&](int, uint64_t i, uint64_t) {
        build(level[i], out);
        return uint64_t(0);
    });
    photons_.resize(n);
    parallelForBlocks(BlockLoop{0, n, kBlock, workers}, nullptr, [&](int, uint64_t first, uint64_t last) {
        for (uint64_t i = first; i < last; ++i) {
            // Reads in input order miss the cache: fetch a few ahead.
            if (i + 32 < last) __builtin_prefetch(&photons[index[i + 32]]);
            photons_[i] = photons[index[i]];
            photons_[i].setAxis(axis[i]);
        }
        return uint64_t(0);
    });
}

template <class Visit>
uint64_t PhotonMap::walk(const float q[3], float r2, Visit&& visit) const {
    const uint32_t n = uint32_t(photons_.size());
    const Photon* photons = photons_.data();
    struct Pending {
        uint32_t node;
        float plane2;  // squared distance from q to the plane that separates it from the node
    };
    Pending stack[64];  // one entry per level at most, and a uint32_t tree has fewer than 32
    int top = 0;
    uint64_t count = 0;
    uint32_t node = 0;
    if (n == 0) return 0;
    // Nodes from bucketFirst on root the last kBucketLevels levels: their subtrees are tested whole, in index
    // order, the loads independent of each other, where a walk would wait for each level's load and branch
    // on it.
    const int last = std::bit_width(n) - 1;
    const uint32_t bucketFirst = last >= kBucketLevels ? (1u << (last - kBucketLevels + 1)) - 1 : UINT32_MAX;
    auto distance2 = [&](uint32_t i) {
        const Photon& p = photons[i];
        const float dx = q[0] - p.position[0], dy = q[1] - p.position[1], dz = q[2] - p.position[2];
        return dx * dx + dy * dy + dz * dz;
    };
    for (;;) {
        for (;;) {
            if (node >= bucketFirst) {
                for (int level = 0; level < kBucketLevels; ++level) {
                    const uint32_t first = ((node + 1) << level) - 1;
                    const uint32_t end = std::min(n, first + (1u << level));
                    for (uint32_t i = first; i < end; ++i) {
                        ++count;
                        if (!visit(distance2(i), i, r2)) return count;
                    }
                }
                break;
            }
            const uint32_t left = 2 * node + 1;
            // The lower levels miss the cache: fetch the grandchildren (4 nodes, 80 contiguous bytes) while
            // this node is tested, two levels ahead of the walk (the children were fetched by the parent).
            const uint64_t grand = 4 * uint64_t(node) + 3;
            if (grand < n) {
                __builtin_prefetch(photons + grand);
                __builtin_prefetch(photons + grand + 3);
            }
            const Photon& p = photons[node];
            ++count;
            const float dx = q[0] - p.position[0], dy = q[1] - p.position[1], dz = q[2] - p.position[2];
            const float d2 = dx * dx + dy * dy + dz * dz;
            if (!visit(d2, node, r2)) return count;
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
            if (top == 0) return count;
        } while (stack[--top].plane2 >= r2);
        node = stack[top].node;
    }
}

uint32_t PhotonMap::nearest(const float q[3], uint64_t* heap, uint32_t k, float r2, uint64_t& visited) const {
    if (k == 0) return 0;
    uint32_t found = 0;
    visited += walk(q, r2, [&](float d2, uint32_t node, float& bound2) {
        if (d2 < bound2) {  // at or within the k-th distance: the index decides a tie
            const uint64_t x = key(d2, node);
            if (found < k) {
                heap[found++] = x;
                std::push_heap(heap, heap + found);
                if (found == k) bound2 = boundPast(heap[0]);
            } else if (x < heap[0]) {
                replaceTop(heap, k, x);
                bound2 = boundPast(heap[0]);
            }
        }
        return true;
    });
    return found;
}

uint32_t PhotonMap::within(const float q[3], float r2, uint64_t* keys, uint32_t cap,
                           uint64_t& visited) const {
    uint32_t found = 0;
    visited += walk(q, r2, [&](float d2, uint32_t node, float& bound2) {
        keys[found] = key(d2, node);  // kept only when within: no branch
        found += d2 < bound2;
        return found < cap;
    });
    return found;
}

GatherResult PhotonMap::gather(const Vec3& p, std::span<Neighbor> buffer, GatherState& state,
                               const GatherSettings& settings) const {
    const float q[3] = {float(p.x), float(p.y), float(p.z)};
    const uint32_t k = uint32_t(std::min<size_t>(buffer.size(), UINT32_MAX / 32));
    const float max2 = settings.maxRadius * settings.maxRadius;
    ++state.queries;
    if (k == 0 || photons_.empty()) return {buffer.first(0), std::isfinite(max2) ? max2 : 0.0f};
    // Room for the photons within the cached radius (about 1.3 k where the density is smooth) and a copy of
    // them to select from.
    const uint32_t cap = 8 * k + 256;
    if (state.scratch.size() < 2 * size_t(cap)) state.scratch.resize(2 * size_t(cap));
    uint64_t* candidates = state.scratch.data();
    uint64_t last = UINT64_MAX;  // the key of the k-th nearest, or of the farthest when fewer are found
    uint32_t found = 0;
    float r2 = max2;
    if (settings.cachedRadius && state.lastRadius2 > 0) {
        r2 = std::min(max2, state.lastRadius2 * settings.cacheGrowth * settings.cacheGrowth);
        // Fewer than k below `lower`, cap or more below `upper`. A range search that finds too few or too
        // many searches again with its bound scaled by the count it found (a photon's share of area, as in a
        // smooth density), kept between the two; after kRangeTries the heap search takes over.
        constexpr int kRangeTries = 4;
        float lower = 0, upper = INFINITY;
        for (int attempt = 0;; ++attempt) {
            found = within(q, r2, candidates, cap, state.nodesVisited);
            if (found >= k && found < cap) {
                // Every photon below r2 is here, so the k smallest keys are the k nearest. Copy them out in
                // walk order (the candidates' order) up to the k-th's key.
                uint64_t* copy = candidates + cap;
                std::copy(candidates, candidates + found, copy);
                last = selectKey(copy, copy + found, copy + (k - 1));
                uint32_t out = 0;
                for (uint32_t i = 0; out < k; ++i) {
                    buffer[out] = {keyDistance2(candidates[i]), uint32_t(candidates[i])};
                    out += candidates[i] <= last;
                }
                state.lastRadius2 = keyDistance2(last);
                return {buffer.first(k), keyDistance2(last)};
            }
            if (found < k && !(r2 < max2)) {
                // Every photon within maxRadius, fewer than k: already in walk order.
                for (uint32_t i = 0; i < found; ++i)
                    buffer[i] = {keyDistance2(candidates[i]), uint32_t(candidates[i])};
                return {buffer.first(found), max2};
            }
            ++state.retries;
            if (attempt + 1 == kRangeTries) break;
            if (found < k) {
                lower = r2;
                r2 *= found > 0 ? std::min(16.0f, 1.5f * float(k) / float(found)) : 16.0f;
            } else {
                upper = r2;
                r2 *= 1.5f * float(k) / float(cap);
            }
            if (!(r2 > lower && r2 < upper)) r2 = 0.5f * (lower + upper);
            r2 = std::min(r2, max2);
        }
        r2 = std::min(upper, max2);  // bounds the k nearest when a search found too many
    }
    found = nearest(q, candidates, k, r2, state.nodesVisited);
    if (found == 0) return {buffer.first(0), std::isfinite(max2) ? max2 : 0.0f};
    last = candidates[0];
    if (found == k) state.lastRadius2 = keyDistance2(last);
    // The heap's photons again, in walk order: the walk within the farthest's distance, up to its key.
    uint32_t out = 0;
    state.nodesVisited += walk(q, boundPast(last), [&](float d2, uint32_t node, float&) {
        buffer[out] = {d2, node};
        out += key(d2, node) <= last;
        return out < found;
    });
    const float radius2 = found == k || !std::isfinite(max2) ? keyDistance2(last) : max2;
    return {buffer.first(found), radius2};
}

double PhotonMap::irradiance(const Vec3& p, const Vec3& normal, std::span<Neighbor> buffer,
                             GatherState& state, const GatherSettings& settings) const {
    return estimate<double>(p, buffer, state, settings, [&](const Photon& ph) {
        return dot(ph.travel(), normal) < 0 ? double(ph.power) : 0.0;
    });
}

}  // namespace facetlight
