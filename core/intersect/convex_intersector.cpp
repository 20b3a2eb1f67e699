#include "intersect/convex_intersector.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include "geometry/halfspace.h"
#include "util/error.h"

// Compiled once per SIMD target (Highway's foreach_target re-includes this file).
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "intersect/convex_intersector.cpp"
#include "hwy/foreach_target.h"  // IWYU pragma: keep

#include "hwy/highway.h"
#include "intersect/convex_search-inl.h"
#include "intersect/detail/convex_kernels.h"

HWY_BEFORE_NAMESPACE();
namespace facetlight {
namespace HWY_NAMESPACE {

bool enterOne(const ConvexIntersector::Planes& p, const Vec3f& o, const Vec3f& d, SurfaceHit& hit) {
    return EnterRay(p, o, d, hit);
}
bool leaveOne(const ConvexIntersector& convex, const Vec3f& o, const Vec3f& d, SurfaceHit& hit) {
    return LeaveStone(convex, o, d, hit);
}
bool enterBeamOne(const ConvexBeamEntry& beam, const Vec3f& o, SurfaceHit& hit) {
    return EnterBeamRay(beam, o, hit);
}
const ConvexKernels* convexKernels() {
    static const ConvexKernels kernels{&enterOne, &leaveOne, &enterBeamOne};
    return &kernels;
}

}  // namespace HWY_NAMESPACE
}  // namespace facetlight
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace facetlight {

HWY_EXPORT(convexKernels);

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

}  // namespace

void ConvexIntersector::Planes::add(const Facet& f) {
    nx.push_back(float(f.normal.x));
    ny.push_back(float(f.normal.y));
    nz.push_back(float(f.normal.z));
    offset.push_back(float(f.offset));
    facet.push_back(f.id);
}

void ConvexIntersector::Planes::pad() {
    count = nx.size();
    while (nx.empty() || nx.size() % kPadding) {
        nx.push_back(0.0f), ny.push_back(0.0f), nz.push_back(0.0f), offset.push_back(1.0f);
        facet.push_back(0);
    }
}

namespace {

// Far above the rounding of t, the exit point and the planes' distances, which is a few float ulps of the
// coordinates (convex_search-inl.h: insideGirdle, LeaveCulled).
double searchMargin(const Bounds3& b) {
    const Vec3 e = b.extent();
    return 1e-4 * (std::max({std::abs(b.lo.x), std::abs(b.lo.y), std::abs(b.lo.z), std::abs(b.hi.x),
                             std::abs(b.hi.y), std::abs(b.hi.z)}) +
                   std::max({e.x, e.y, e.z}));
}

// The radius of the widest upright cylinder about (cx, cy) inside plane `f` over heights [zLow, zHigh], with
// the plane as the searches see it (in float); -inf for a plane more than 30 deg off vertical.
double cylinderInside(const Facet& f, double cx, double cy, double zLow, double zHigh) {
    const double nx = float(f.normal.x), ny = float(f.normal.y), nz = float(f.normal.z),
                 offset = float(f.offset), across = std::hypot(nx, ny);
    if (!(std::abs(nz) <= 0.5 * std::hypot(across, nz))) return -kInf;
    const double atAxis = offset - nx * cx - ny * cy;
    return std::min(atAxis - nz * zLow, atAxis - nz * zHigh) / across;
}

// The girdle split (ConvexIntersector::Girdle) of a stone, with no planes where it does not pay.
ConvexIntersector::Girdle girdleOf(const Stone& stone) {
    constexpr double kRound = 0.98;  // the cylinder's radius against the stone's widest, at least
    constexpr size_t kMinFacets = 8;
    const Bounds3& b = stone.bounds;
    const double cx = b.center().x, cy = b.center().y,
                 size = std::max(std::max(b.extent().x, b.extent().y), b.extent().z);
    const double margin = searchMargin(b);
    double widest = 0;
    for (const Vec3& v : stone.vertices) widest = std::max(widest, std::hypot(v.x - cx, v.y - cy));
    ConvexIntersector::Girdle g;
    double radius = kInf;
    std::vector<bool> inGirdle(stone.facets.size());
    for (const Facet& f : stone.facets) {
        const double r = cylinderInside(f, cx, cy, b.lo.z - 2 * margin, b.hi.z + 2 * margin);
        if (r >= kRound * widest) inGirdle[f.id] = true, radius = std::min(radius, r);
    }
    radius -= margin;
    if (std::count(inGirdle.begin(), inGirdle.end(), true) < ptrdiff_t(kMinFacets) || !(radius > 0)) return g;
    for (const Facet& f : stone.facets) (inGirdle[f.id] ? g.facets : g.others).add(f);
    g.facets.pad(), g.others.pad();
    g.cx = float(cx), g.cy = float(cy);
    g.radius2 = float(radius * radius);
    // The table and the culet lie at the stone's top and bottom: exits through them are inside the range.
    g.zLow = float(b.lo.z - margin), g.zHigh = float(b.hi.z + margin);
    g.maxT = float(2 * size);
    return g;
}

// A facet's normal as the searches see it (in float).
Vec3 searchNormal(const Facet& f) {
    return {float(f.normal.x), float(f.normal.y), float(f.normal.z)};
}

// The facets in groups of nearby normals: spherical k-means from spread-out seeds (each next seed the normal
// farthest from those taken), about kPlanesPerGroup planes to a group, at most Cull::kMaxGroups.
// Deterministic; empty groups are dropped.
std::vector<std::vector<uint32_t>> normalGroups(const Stone& stone) {
    constexpr size_t kPlanesPerGroup = 12, kMaxGroups = ConvexIntersector::Cull::kMaxGroups, kRounds = 20;
    const size_t n = stone.facets.size(),
                 k = std::min(kMaxGroups, (n + kPlanesPerGroup - 1) / kPlanesPerGroup);
    std::vector<Vec3> axis{searchNormal(stone.facets[0])};
    std::vector<double> nearest(n, -kInf);  // the largest cosine to a seed so far
    while (axis.size() < k) {
        size_t far = 0;
        for (size_t i = 0; i < n; ++i) {
            nearest[i] = std::max(nearest[i], dot(searchNormal(stone.facets[i]), axis.back()));
            if (nearest[i] < nearest[far]) far = i;
        }
        axis.push_back(searchNormal(stone.facets[far]));
    }
    std::vector<size_t> group(n);
    for (size_t round = 0; round < kRounds; ++round) {
        std::vector<Vec3> sum(k);
        for (size_t i = 0; i < n; ++i) {
            const Vec3 normal = searchNormal(stone.facets[i]);
            for (size_t g = 0; g < k; ++g)
                if (dot(normal, axis[g]) > dot(normal, axis[group[i]])) group[i] = g;
            sum[group[i]] = sum[group[i]] + normal;
        }
        for (size_t g = 0; g < k; ++g)
            if (length(sum[g]) > 0) axis[g] = normalize(sum[g]);
    }
    std::vector<std::vector<uint32_t>> groups(k);
    for (size_t i = 0; i < n; ++i) groups[group[i]].push_back(uint32_t(i));
    std::erase_if(groups, [](const std::vector<uint32_t>& g) { return g.empty(); });
    return groups;
}

// The largest float below x (x itself when it is a float): a bound that stays on the safe side.
float floatBelow(double x) {
    const float f = float(x);
    return double(f) > x ? std::nextafter(f, -kInf) : f;
}
float floatAbove(double x) {
    const float f = float(x);
    return double(f) < x ? std::nextafter(f, kInf) : f;
}

// The Cull of a stone (ConvexIntersector::Cull), with no groups where it does not apply.
ConvexIntersector::Cull cullOf(const Stone& stone) {
    ConvexIntersector::Cull c;
    if (stone.facets.size() < ConvexIntersector::Cull::kMinPlanes) return c;
    const double margin = searchMargin(stone.bounds);
    const std::vector<std::vector<uint32_t>> groups = normalGroups(stone);
    // Each row's axis in float (as the search has it) and the hull's bound along it: a margin beyond the
    // stone's farthest vertex.
    std::vector<Vec3> axis;
    for (const std::vector<uint32_t>& g : groups) {
        Vec3 sum;
        for (uint32_t f : g) sum = sum + searchNormal(stone.facets[f]);
        const Vec3 a = normalize(sum);
        axis.push_back({float(a.x), float(a.y), float(a.z)});
    }
    for (const Vec3& a :
         {Vec3{1, 0, 0}, Vec3{-1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, -1, 0}, Vec3{0, 0, 1}, Vec3{0, 0, -1}})
        axis.push_back(a);
    std::vector<NamedPlane> hull;
    for (const Vec3& a : axis) {
        double reach = -kInf;
        for (const Vec3& v : stone.vertices) reach = std::max(reach, dot(a, v));
        c.ax.push_back(float(a.x)), c.ay.push_back(float(a.y)), c.az.push_back(float(a.z));
        c.hullBound.push_back(floatAbove(reach + margin));
        // Widened by the margin again: the hull's exit as the search rounds it lies inside.
        hull.push_back({{a, double(c.hullBound.back()) + margin}, "hull"});
    }
    const PolygonMesh h = intersectHalfSpaces(hull);
    // min axis . x over the widened hull where x lies less than the margin inside plane (n, offset): at a
    // vertex of the hull beyond that level, or where an edge crosses it.
    auto leastNear = [&](const Vec3& a, const Vec3& n, double offset) {
        const double level = offset - margin;
        double least = kInf;
        for (const Vec3& v : h.vertices)
            if (dot(n, v) >= level) least = std::min(least, dot(a, v));
        for (const PolygonMesh::Polygon& poly : h.polygons) {
            for (size_t i = 0; i < poly.vertices.size(); ++i) {
                const Vec3 &u = h.vertices[poly.vertices[i]],
                           &v = h.vertices[poly.vertices[(i + 1) % poly.vertices.size()]];
                const double du = dot(n, u) - level, dv = dot(n, v) - level;
                if ((du < 0) == (dv < 0)) continue;
                least = std::min(least, dot(a, u + (v - u) * (du / (du - dv))));
            }
        }
        return least;
    };
    for (size_t g = 0; g < groups.size(); ++g) {
        ConvexIntersector::Planes planes;
        double skip = kInf;
        for (uint32_t f : groups[g]) {
            planes.add(stone.facets[f]);
            skip = std::min(skip,
                            leastNear(axis[g], searchNormal(stone.facets[f]), float(stone.facets[f].offset)));
        }
        planes.pad();
        c.groups.push_back(std::move(planes));
        c.skipBelow.push_back(floatBelow(skip - margin));
    }
    c.rows = axis.size();
    c.skipBelow.resize(c.rows, -kInf);
    for (size_t row = c.rows; row % ConvexIntersector::Planes::kPadding; ++row) {
        c.ax.push_back(0), c.ay.push_back(0), c.az.push_back(0);
        c.hullBound.push_back(kInf), c.skipBelow.push_back(-kInf);
    }
    const Vec3 e = stone.bounds.extent();
    c.maxT = float(2 * std::max({e.x, e.y, e.z}));
    return c;
}

std::atomic<bool> culling{true};

}  // namespace

void ConvexIntersector::setCulling(bool on) {
    culling = on;
}

ConvexIntersector::ConvexIntersector(const Stone& stone) : kernels_(HWY_DYNAMIC_DISPATCH(convexKernels)()) {
    if (!stone.convex)
        throw Error("the convex intersector needs a convex stone; '" + stone.name + "' is not");
    if (stone.facets.empty()) throw Error("stone '" + stone.name + "' has no facets");
    for (const Facet& f : stone.facets) planes_.add(f);
    planes_.pad();
    girdle_ = girdleOf(stone);
    if (!girdle_.facets.count && culling) cull_ = cullOf(stone);
}

bool ConvexIntersector::enter(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const {
    return kernels_->enter(planes_, origin, dir, hit);
}

bool ConvexIntersector::leave(const Vec3f& origin, const Vec3f& dir, SurfaceHit& hit) const {
    return kernels_->leave(*this, origin, dir, hit);
}

void ConvexBeamEntry::Planes::add(float a_, const Vec3f& m, uint32_t f) {
    a.push_back(a_);
    mx.push_back(m.x);
    my.push_back(m.y);
    mz.push_back(m.z);
    facet.push_back(f);
}

void ConvexBeamEntry::Planes::pad(float a_) {
    count = a.size();
    while (a.empty() || a.size() % ConvexIntersector::Planes::kPadding) add(a_, {}, 0);
}

namespace {

// The beam's crossings of the given facets' planes.
ConvexBeamEntry::Crossings crossingsOf(const Stone& stone, const Vec3f& dir, const std::vector<bool>& take) {
    ConvexBeamEntry::Crossings c;
    for (const Facet& f : stone.facets) {
        if (!take[f.id]) continue;
        const Vec3f n(f.normal);
        const float den = dot(dir, n), offset = float(f.offset);
        if (den == 0) {
            c.parallelNormal.push_back(n);
            c.parallelOffset.push_back(offset);
        } else {
            (den < 0 ? c.in : c.out).add(offset / den, n * (1 / den), f.id);
        }
    }
    c.in.pad(-kInf);
    c.out.pad(kInf);
    return c;
}

}  // namespace

ConvexBeamEntry::ConvexBeamEntry(const Stone& stone, const Vec3f& dir)
    : dir_(dir), kernels_(HWY_DYNAMIC_DISPATCH(convexKernels)()) {
    if (!stone.convex)
        throw Error("the convex intersector needs a convex stone; '" + stone.name + "' is not");
    planes_ = crossingsOf(stone, dir, std::vector<bool>(stone.facets.size(), true));
    girdle_ = girdleOf(stone);
    if (!girdle_.facets.count) return;
    std::vector<bool> inGirdle(stone.facets.size());
    for (size_t i = 0; i < girdle_.facets.count; ++i) inGirdle[girdle_.facets.facet[i]] = true;
    girdleFacets_ = crossingsOf(stone, dir, inGirdle);
    inGirdle.flip();
    otherFacets_ = crossingsOf(stone, dir, inGirdle);
}

bool ConvexBeamEntry::enter(const Vec3f& origin, SurfaceHit& hit) const {
    return kernels_->enterBeam(*this, origin, hit);
}

}  // namespace facetlight
#endif
