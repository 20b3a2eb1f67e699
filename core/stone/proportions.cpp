#include "stone/proportions.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "stone/girdle.h"

namespace facetlight {

namespace {

// The vertices a facet of `region` shares with the girdle: those of the girdle facets or, on a knife edge,
// of the other side.
std::vector<bool> girdleVertices(const Stone& stone, Region region) {
    std::vector<bool> atGirdle(stone.vertices.size(), false);
    const Region otherSide = region == Region::Crown ? Region::Pavilion : Region::Crown;
    for (const auto& f : stone.facets) {
        if (f.region != Region::Girdle && f.region != otherSide) continue;
        for (uint32_t v : f.outline) atGirdle[v] = true;
    }
    return atGirdle;
}

double slopeDeg(const Facet& f) {
    return degrees(std::acos(std::clamp(std::fabs(f.normal.z), 0.0, 1.0)));
}

// The main facets: those that run from the table (or culet) down to the girdle; failing that, the largest
// facet at the girdle. A facet reaches the girdle where it shares a vertex with a girdle facet (or, on a
// knife edge, with the other side) or comes down to the girdle's thinnest point: on a fancy outline the
// girdle's height varies, so no one height tells. Of those at the table, the largest of those that come
// closest to the girdle (within a tenth of the crown's height: a pear's stars touch the girdle at its
// point, but its bezels come much lower).
const Facet* mainFacet(const Stone& stone, double scale, Region region, double girdleZ, double apexZ) {
    const double eps = 1e-6 * scale, side = region == Region::Crown ? 1 : -1;
    const double closeEnough = 0.1 * std::fabs(apexZ - girdleZ);
    const std::vector<bool> atGirdle = girdleVertices(stone, region);
    const Facet* best = nullptr;
    bool bestAtApex = false;
    double bestHeight = 0;  // of the facet's lowest point above the girdle (crown; below it, pavilion)
    auto outranksBest = [&](const Facet& f, bool atApex, double height) {
        if (!best) return true;
        if (atApex != bestAtApex) return atApex;
        if (std::fabs(height - bestHeight) > closeEnough) return height < bestHeight;
        return f.area > best->area;
    };
    for (const auto& f : stone.facets) {
        if (f.region != region) continue;
        bool touchesGirdle = false, touchesApex = false;
        double height = INFINITY;
        for (uint32_t v : f.outline) {
            const double z = stone.vertices[v].z;
            height = std::min(height, side * (z - girdleZ));
            touchesGirdle |= atGirdle[v];
            touchesApex |= std::fabs(z - apexZ) <= eps;
        }
        if (!touchesGirdle && height > eps) continue;
        if (!outranksBest(f, touchesApex, height)) continue;
        best = &f, bestAtApex = touchesApex, bestHeight = height;
    }
    return best;
}

// A round brilliant's stars, upper halves and lower halves, told apart by what they touch (see
// Proportions); nothing when the stone has no such tier.
void measureMinorTiers(const Stone& stone, double scale, const Facet& table, double radius, double bottom,
                       Proportions& p) {
    const double eps = 1e-6 * scale;
    std::vector<bool> atTable(stone.vertices.size(), false);
    for (uint32_t v : table.outline) atTable[v] = true;
    const std::vector<bool> crownGirdle = girdleVertices(stone, Region::Crown);
    const std::vector<bool> pavilionGirdle = girdleVertices(stone, Region::Pavilion);
    auto touches = [&](const Facet& f, const std::vector<bool>& set) {
        return std::any_of(f.outline.begin(), f.outline.end(), [&](uint32_t v) { return bool(set[v]); });
    };
    auto radiusOf = [&](uint32_t v) { return std::hypot(stone.vertices[v].x, stone.vertices[v].y); };
    struct Mean {
        double sum = 0;
        int count = 0;
        void add(double v) { sum += v, ++count; }
        std::optional<double> value() const {
            return count ? std::optional<double>(sum / count) : std::nullopt;
        }
    };
    Mean star, upper, lower, starLength, lowerLength;
    for (const auto& f : stone.facets) {
        if (f.region == Region::Crown) {
            const bool atT = touches(f, atTable), atG = touches(f, crownGirdle);
            if (atT && !atG) {
                star.add(slopeDeg(f));
                // From the star's base on the table edge (its point nearest the axis) to its tip.
                double tip = 0, base = INFINITY;
                for (size_t i = 0; i < f.outline.size(); ++i) {
                    const Vec3& a = stone.vertices[f.outline[i]];
                    const Vec3& b = stone.vertices[f.outline[(i + 1) % f.outline.size()]];
                    tip = std::max(tip, std::hypot(a.x, a.y));
                    const Vec3 d{b.x - a.x, b.y - a.y, 0};
                    const double t =
                        std::clamp(-(a.x * d.x + a.y * d.y) / std::max(dot(d, d), 1e-300), 0.0, 1.0);
                    base = std::min(base, std::hypot(a.x + t * d.x, a.y + t * d.y));
                }
                starLength.add(100 * (tip - base) / (radius - base));
            } else if (atG && !atT) {
                upper.add(slopeDeg(f));
            }
        } else if (f.region == Region::Pavilion && touches(f, pavilionGirdle)) {
            const bool atApex = std::any_of(f.outline.begin(), f.outline.end(),
                                            [&](uint32_t v) { return stone.vertices[v].z <= bottom + eps; });
            if (atApex) continue;
            lower.add(slopeDeg(f));
            double inner = INFINITY;
            for (uint32_t v : f.outline) inner = std::min(inner, radiusOf(v));
            lowerLength.add(100 * (radius - inner) / radius);
        }
    }
    if (!star.count || !upper.count || !lower.count) return;
    p.starAngleDeg = star.value(), p.upperHalfAngleDeg = upper.value(), p.lowerHalfAngleDeg = lower.value();
    p.starPct = starLength.value(), p.lowerHalfPct = lowerLength.value();
}

}  // namespace

Proportions measureProportions(const Stone& stone, double scale) {
    Proportions p;
    const Bounds3& b = stone.bounds;
    p.length = std::max(b.extent().x, b.extent().y);
    p.width = std::min(b.extent().x, b.extent().y);
    // Round: no vertex reaches much beyond the circle inscribed in the extents (a square's corners do; a
    // 16-sided girdle's reach 1 / cos 11.25 = 1.0196 times as far).
    double maxRadius = 0;
    for (const auto& v : stone.vertices) maxRadius = std::max(maxRadius, std::hypot(v.x, v.y));
    const bool round = p.length <= p.width * 1.01 && maxRadius <= 0.25 * (p.length + p.width) * 1.025;
    p.diameter = round ? 0.5 * (p.length + p.width) : p.width;
    const double d = p.diameter;
    const GirdleBand band = girdleBand(stone, scale);
    const double top = b.hi.z, bottom = b.lo.z;
    p.totalDepthPct = 100 * (top - bottom) / d;
    p.girdlePct = 100 * (band.top - band.bottom) / d;
    p.girdleThickestPct = std::max(*p.girdlePct, 100 * girdleThickest(stone, scale) / d);
    const Facet* crownMain =
        stone.facetCount(Region::Crown) > 0 ? mainFacet(stone, scale, Region::Crown, band.top, top) : nullptr;
    const Facet* pavilionMain = stone.facetCount(Region::Pavilion) > 0
                                    ? mainFacet(stone, scale, Region::Pavilion, band.bottom, bottom)
                                    : nullptr;
    double crownRim = band.top, pavilionRim = band.bottom;
    if (crownMain) {
        p.crownAngleDeg = slopeDeg(*crownMain);
        crownRim = INFINITY;
        for (uint32_t v : crownMain->outline) crownRim = std::min(crownRim, stone.vertices[v].z);
    }
    if (pavilionMain) {
        p.pavilionAngleDeg = slopeDeg(*pavilionMain);
        pavilionRim = -INFINITY;
        for (uint32_t v : pavilionMain->outline) pavilionRim = std::max(pavilionRim, stone.vertices[v].z);
    }
    p.crownHeightPct = 100 * (top - crownRim) / d;
    p.pavilionDepthPct = 100 * (pavilionRim - bottom) / d;
    const Facet* table = nullptr;
    for (const auto& f : stone.facets)
        if (f.region == Region::Table) table = &f;
    if (table) {
        double maxR = 0, lo = INFINITY, hi = -INFINITY;
        for (uint32_t v : table->outline) {
            const Vec3& q = stone.vertices[v];
            maxR = std::max(maxR, std::hypot(q.x, q.y));
            lo = std::min(lo, q.y), hi = std::max(hi, q.y);
        }
        p.tablePct = 100 * (round ? 2 * maxR : hi - lo) / d;
        if (round) measureMinorTiers(stone, scale, *table, d / 2, bottom, p);
    }
    if (p.crownHeightPct && *p.crownHeightPct <= 1e-9) p.crownHeightPct.reset(), p.crownAngleDeg.reset();
    return p;
}

}  // namespace facetlight
