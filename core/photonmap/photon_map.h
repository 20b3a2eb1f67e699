#pragma once
// The photon map: a balanced kd-tree over the photons, stored as a left-balanced heap in one flat array
// (after Jensen, "Realistic Image Synthesis Using Photon Mapping", 2001), with a k-nearest gather and density
// estimates for the renderer.
//
// Layout: photons()[0] is the root; node i has children 2i + 1 and 2i + 2 where they are < size(); its split
// plane is axis photons()[i].axis() at photons()[i].position[axis]; its left subtree holds no larger and its
// right subtree no smaller coordinates on that axis.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/geometry.h"
#include "photonmap/photon.h"

namespace facetlight {

struct Neighbor {
    float distance2;  // squared distance to the query point
    uint32_t index;   // into PhotonMap::photons()
    bool operator<(const Neighbor& b) const { return distance2 < b.distance2; }
};

struct GatherSettings {
    float maxRadius = INFINITY;
    // Bound each search by cacheGrowth x the radius of the thread's last complete gather and search again
    // unbounded when that finds fewer than k: less work when successive queries are near each other.
    bool cachedRadius = true;
    float cacheGrowth = 1.15f;
    // Jensen's cone filter constant (weights 1 - d / (coneK r)), >= 1; 0 weights every photon equally.
    float coneK = 0;
};

// One per thread, never shared: the cached radius, the candidates' buffer (sized at the first gather, so
// that gathers allocate nothing after it) and counters of the work done.
struct GatherState {
    float lastRadius2 = 0;  // 0 until a gather found k photons
    uint64_t queries = 0;
    uint64_t retries = 0;  // cached-radius searches that found fewer than k, or too many, and were repeated
    uint64_t nodesVisited = 0;  // = photons distance-tested: every node is a photon
    std::vector<uint64_t> scratch;
};

struct GatherResult {
    // In the order of the tree walk from the query point (near side first; the last levels' subtrees in index
    // order), which depends on the point alone: sums over them have the same bits whatever the search's
    // bound was.
    std::span<Neighbor> neighbors;
    // Squared radius of the disc the estimate divides by: the k-th distance when k were found, else
    // maxRadius^2 (or, with no maxRadius, the farthest photon found).
    float radius2 = 0;
};

class PhotonMap {
  public:
    PhotonMap() = default;
    // Builds the tree; the result depends only on the order of `photons`, never on `threads` (the top levels
    // are split between threads). Throws Error on a non-finite position.
    explicit PhotonMap(std::vector<Photon> photons, int threads = 1);

    size_t size() const { return photons_.size(); }
    bool empty() const { return photons_.empty(); }
    std::span<const Photon> photons() const { return photons_; }

    // The k = buffer.size() photons nearest to p within settings.maxRadius (fewer where there are fewer),
    // written to buffer; at equal distances the lower index in photons() is the nearer. The answer depends
    // only on p, k and maxRadius, never on the state's history. Allocates nothing after the state's first.
    GatherResult gather(const Vec3& p, std::span<Neighbor> buffer, GatherState& state,
                        const GatherSettings& settings = {}) const;

    // Density estimate sum(weight(photon) * filter) / (pi r^2) over the k nearest photons, where weight maps
    // a photon to a value of type T (power, or a colour from its power and wavelength). Zero where the
    // gather finds nothing.
    template <class T, class Weight>
    T estimate(const Vec3& p, std::span<Neighbor> buffer, GatherState& state, const GatherSettings& settings,
               Weight&& weight) const;

    // Irradiance (power per area) at p on a surface facing `normal`, from photons arriving on that side.
    double irradiance(const Vec3& p, const Vec3& normal, std::span<Neighbor> buffer, GatherState& state,
                      const GatherSettings& settings = {}) const;

  private:
    // The walk from q, near side first, below the squared bound r2: visit(d2, node, r2) for every photon it
    // reaches, which may lower r2 and returns false to stop; the subtrees of the last levels are tested
    // whole, in index order. Returns the photons tested.
    template <class Visit>
    uint64_t walk(const float q[3], float r2, Visit&& visit) const;
    // The k smallest keys (see key() in the .cpp) below the squared bound r2 as a max-heap; returns the
    // count.
    uint32_t nearest(const float q[3], uint64_t* heap, uint32_t k, float r2, uint64_t& visited) const;
    // The keys of every photon below r2, in walk order; returns the count, or cap when there are cap or more.
    uint32_t within(const float q[3], float r2, uint64_t* keys, uint32_t cap, uint64_t& visited) const;

    std::vector<Photon> photons_;
};

template <class T, class Weight>
T PhotonMap::estimate(const Vec3& p, std::span<Neighbor> buffer, GatherState& state,
                      const GatherSettings& settings, Weight&& weight) const {
    const GatherResult g = gather(p, buffer, state, settings);
    T sum{};
    if (g.neighbors.empty() || !(g.radius2 > 0)) return sum;
    double norm = kPi * g.radius2;
    if (settings.coneK > 0) {
        // Jensen eq. 7.6: the cone filter loses 2 / (3k) of a uniform density's mass.
        const double invKr = 1.0 / (settings.coneK * std::sqrt(double(g.radius2)));
        for (const Neighbor& n : g.neighbors)
            sum += weight(photons_[n.index]) * (1.0 - std::sqrt(double(n.distance2)) * invKr);
        norm *= 1.0 - 2.0 / (3.0 * settings.coneK);
    } else {
        for (const Neighbor& n : g.neighbors) sum += weight(photons_[n.index]);
    }
    return sum * (1.0 / norm);
}

}  // namespace facetlight
