#include "pictures/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pictures/colormap.h"
#include "util/error.h"
#include "util/number_text.h"

namespace facetlight {
namespace {

std::string percent(double share, int decimals) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f%%", decimals, 100 * share);
    return buffer;
}

constexpr int kWidth = 1100, kHeight = 770;
constexpr Point2 kCentre[2] = {{kWidth * 0.25 + 5, 350}, {kWidth * 0.75 - 5, 350}};

}  // namespace

HeatmapLayout heatmapLayout(const Stone& stone) {
    constexpr double kHalf = 250;  // pixels from a diagram's centre to the stone's widest point
    double extent = 0;
    for (const Vec3& v : stone.vertices) extent = std::max({extent, std::fabs(v.x), std::fabs(v.y)});
    if (!(extent > 0)) extent = 1;
    // side 0: table and crown from above; side 1: pavilion from below (mirrored in x, as when turned over
    // about the y axis). Facets are drawn far side first so that the near ones cover them.
    auto onSide = [&](const Facet& f, int side) {
        return side == 0 ? (f.region == Region::Table || f.region == Region::Crown)
                         : f.region == Region::Pavilion;
    };
    auto project = [&](const Vec3& v, int side) -> Point2 {
        const double x = side == 0 ? v.x : -v.x;
        return {kCentre[side][0] + x / extent * kHalf, kCentre[side][1] - v.y / extent * kHalf};
    };
    HeatmapLayout layout{kWidth, kHeight, {}};
    for (int side = 0; side < 2; ++side) {
        std::vector<uint32_t> order;
        for (uint32_t f = 0; f < stone.facets.size(); ++f) {
            if (onSide(stone.facets[f], side)) order.push_back(f);
        }
        std::sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) {
            const double za = stone.facets[a].centroid.z, zb = stone.facets[b].centroid.z;
            return side == 0 ? za < zb : za > zb;
        });
        for (uint32_t f : order) {
            HeatmapFacet& drawn = layout.facets.emplace_back(
                HeatmapFacet{f, side, {}, project(stone.facets[f].centroid, side)});
            for (uint32_t v : stone.facets[f].outline)
                drawn.outline.push_back(project(stone.vertices[v], side));
        }
    }
    return layout;
}

nlohmann::json toJson(const HeatmapLayout& layout, const Stone& stone) {
    nlohmann::json facets = nlohmann::json::array();
    for (const HeatmapFacet& f : layout.facets) {
        nlohmann::json points = nlohmann::json::array();
        // A tenth of a pixel is finer than any pointer.
        for (const Point2& p : f.outline)
            points.push_back({std::round(p[0] * 10) / 10, std::round(p[1] * 10) / 10});
        facets.push_back({{"id", stone.facets[f.facet].id},
                          {"name", stone.facets[f.facet].name},
                          {"side", f.side == 0 ? "crown" : "pavilion"},
                          {"points", points}});
    }
    return {{"width", layout.width}, {"height", layout.height}, {"facets", facets}};
}

namespace {

// What a heat-map says about the shares it shows.
struct ShareWording {
    std::string title;  // above the diagrams
    std::string whole;  // what the shares are of, with its count, e.g. "of the photons hitting the stone (n)"
    std::string bar;    // the colour bar's label
};

// The top of the colour scale: the 95th percentile of the shares of the drawn facets other than the table,
// rounded up to a tick of the colour bar. The table takes a large share of most designs; on a scale up to it
// every other facet would be the same dark colour. The largest share when no other facet has any.
double scaleTop(const Stone& stone, const HeatmapLayout& layout, const std::vector<double>& share) {
    std::vector<double> others;
    double largest = 0;
    for (const HeatmapFacet& f : layout.facets) {
        largest = std::max(largest, share[f.facet]);
        if (stone.facets[f.facet].region != Region::Table) others.push_back(share[f.facet]);
    }
    double top = 0;
    if (!others.empty()) {
        std::sort(others.begin(), others.end());
        top = others[size_t(std::ceil(0.95 * double(others.size()))) - 1];
    }
    if (!(top > 0)) top = largest;
    if (!(top > 0)) return 0;
    double step;
    niceTicks(100 * top, step);
    return std::ceil(100 * top / step - 1e-9) * step / 100;
}

// The part of `polygon` where a x + b y <= c (Sutherland-Hodgman against one half-plane).
std::vector<Point2> clipped(const std::vector<Point2>& polygon, double a, double b, double c) {
    std::vector<Point2> out;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Point2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        const double dp = a * p[0] + b * p[1] - c, dq = a * q[0] + b * q[1] - c;
        if (dp <= 0) out.push_back(p);
        if ((dp < 0) != (dq < 0) && dp != dq) {
            const double t = dp / (dp - dq);
            out.push_back({p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1])});
        }
    }
    return out;
}

// Diagonal stripes over a polygon: the mark of a share beyond the colour scale.
void hatch(Image& image, const std::vector<Point2>& polygon, const Rgb& c) {
    constexpr double kPeriod = 12, kStripe = 3;
    double lo = INFINITY, hi = -INFINITY;
    for (const Point2& p : polygon) {
        lo = std::min(lo, p[0] + p[1]);
        hi = std::max(hi, p[0] + p[1]);
    }
    for (double s = std::floor(lo / kPeriod) * kPeriod; s < hi; s += kPeriod) {
        const std::vector<Point2> stripe = clipped(clipped(polygon, 1, 1, s + kStripe), -1, -1, -s);
        if (stripe.size() >= 3) fillPolygon(image, stripe, c);
    }
}

// Whether a w x h box centred on `c` lies inside the convex polygon (either orientation).
bool boxInside(const std::vector<Point2>& polygon, const Point2& c, double w, double h) {
    double area = 0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const Point2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
        area += p[0] * q[1] - q[0] * p[1];
    }
    for (const Point2 corner : {Point2{c[0] - w / 2, c[1] - h / 2}, Point2{c[0] + w / 2, c[1] - h / 2},
                                Point2{c[0] + w / 2, c[1] + h / 2}, Point2{c[0] - w / 2, c[1] + h / 2}}) {
        for (size_t i = 0; i < polygon.size(); ++i) {
            const Point2 &p = polygon[i], &q = polygon[(i + 1) % polygon.size()];
            const double side = (q[0] - p[0]) * (corner[1] - p[1]) - (q[1] - p[1]) * (corner[0] - p[0]);
            if (side * area < 0) return false;
        }
    }
    return true;
}

// A facet's share in percent, without the sign (the colour bar says it): to 0.1 %, finer below it.
std::string shareLabel(double share) {
    if (share == 0) return "0";
    return formatNumber(100 * share < 0.1 ? "%.2f" : "%.1f", 100 * share);
}

// The facet diagram of `share` (one per facet, in [0, 1]) on a colour scale that shows the differences
// between the facets (scaleTop); facets beyond it are hatched and named under the colour bar. Each facet
// that holds its label at a legible size (11 pixels and up) carries its share.
Image shareHeatmap(const Stone& stone, const std::vector<double>& share, const ShareWording& words) {
    const HeatmapLayout layout = heatmapLayout(stone);
    Image image(layout.width, layout.height, {1, 1, 1});
    const Rgb ink{0.1f, 0.1f, 0.1f};
    const double top = scaleTop(stone, layout, share);
    const auto beyond = [&](const HeatmapFacet& f) { return share[f.facet] > top * (1 + 1e-9); };

    std::vector<const HeatmapFacet*> clippedFacets;
    for (const HeatmapFacet& f : layout.facets) {
        fillPolygon(image, f.outline, viridis(top > 0 ? share[f.facet] / top : 0));
        if (beyond(f)) {
            hatch(image, f.outline, ink);
            clippedFacets.push_back(&f);
        }
        drawPolyline(image, f.outline, true, 1.2, ink);
    }
    for (const HeatmapFacet& f : layout.facets) {
        const std::string label = shareLabel(share[f.facet]);
        for (const double scale : {2.0, 1.6}) {
            // On hatching the label sits on a patch of the top colour.
            const double w = textWidth(label, scale) + 6, h = textHeight(scale) + 6;
            if (!boxInside(f.outline, f.centroid, w, h)) continue;
            const double t = top > 0 ? std::min(1.0, share[f.facet] / top) : 0;
            if (beyond(f)) {
                const double x0 = f.centroid[0] - w / 2, y0 = f.centroid[1] - h / 2;
                const Point2 patch[4] = {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
                fillPolygon(image, patch, viridis(1));
            }
            drawText(image, f.centroid[0], f.centroid[1] - textHeight(scale) / 2 + 0.5, label, scale,
                     contrastOn(t), Align::Center);
            break;
        }
    }
    for (int side = 0; side < 2; ++side) {
        const char* title = side == 0 ? "Crown and table, from above" : "Pavilion, from below";
        drawText(image, kCentre[side][0], 70, title, 2.5, ink, Align::Center);
    }

    drawText(image, kWidth / 2.0, 14, words.title, 3, ink, Align::Center);
    std::array<double, kRegionCount> regionShare{};
    for (size_t f = 0; f < stone.facets.size(); ++f) regionShare[size_t(stone.facets[f].region)] += share[f];
    const std::string summary = words.whole + ": table " + percent(regionShare[size_t(Region::Table)], 1) +
                                ", crown " + percent(regionShare[size_t(Region::Crown)], 1) + ", pavilion " +
                                percent(regionShare[size_t(Region::Pavilion)], 1) + ", girdle " +
                                percent(regionShare[size_t(Region::Girdle)], 1);
    drawText(image, kWidth / 2.0, 44, summary, 2, ink, Align::Center);

    constexpr double kBarX = 200, kBarW = kWidth - 400, kBarH = 24, kBarY = kHeight - 124;
    drawColourBar(image, kBarX, kBarY, kBarW, kBarH, top > 0 ? 100 * top : 1, words.bar, 2);
    if (!clippedFacets.empty()) {
        // The bar's arrow past its end stands for the shares beyond it, hatched like their facets.
        const std::vector<Point2> arrow = {
            {kBarX + kBarW, kBarY}, {kBarX + kBarW + 22, kBarY + kBarH / 2}, {kBarX + kBarW, kBarY + kBarH}};
        fillPolygon(image, arrow, viridis(1));
        hatch(image, arrow, ink);
        drawPolyline(image, arrow, true, 1, ink);
        std::sort(
            clippedFacets.begin(), clippedFacets.end(),
            [&](const HeatmapFacet* a, const HeatmapFacet* b) { return share[a->facet] > share[b->facet]; });
        std::string names;
        for (size_t i = 0; i < std::min<size_t>(clippedFacets.size(), 3); ++i) {
            std::string name = stone.facets[clippedFacets[i]->facet].name;
            std::replace(name.begin(), name.end(), '_', ' ');
            names += (i ? ", " : "") + name + " " + percent(share[clippedFacets[i]->facet], 1);
        }
        if (clippedFacets.size() > 3) names += " and " + std::to_string(clippedFacets.size() - 3) + " more";
        drawText(image, kWidth / 2.0, kBarY + kBarH + 12 + 2 * (textHeight(2) + 4) + 4,
                 "Hatched: beyond the scale (" + names + ")", 2, ink, Align::Center);
    }
    return image;
}

}  // namespace

Image facetHeatmap(const Stone& stone, const FacetStats& stats) {
    if (stats.facets.size() != stone.facets.size())
        throw Error("statistics do not belong to stone '" + stone.name + "'");
    const double hit = double(std::max<uint64_t>(stats.hit, 1));
    std::vector<double> share;
    for (const FacetCounts& c : stats.facets) share.push_back(double(c.leaving) / hit);
    return shareHeatmap(stone, share,
                        {"Share of the light leaving through each facet",
                         "of the photons hitting the stone (" + std::to_string(stats.hit) + ")",
                         "share of the light leaving through the facet (%)"});
}

Image fireHeatmap(const Stone& stone, const FireStats& fire) {
    if (fire.colouredByFacet.size() != stone.facets.size())
        throw Error("fire statistics do not belong to stone '" + stone.name + "'");
    const double coloured = double(std::max<uint64_t>(fire.coloured, 1));
    std::vector<double> share;
    for (uint64_t c : fire.colouredByFacet) share.push_back(double(c) / coloured);
    return shareHeatmap(stone, share,
                        {"Share of the fire leaving through each facet",
                         "of the coloured exits (" + std::to_string(fire.coloured) + ")",
                         "share of the fire leaving through the facet (%)"});
}

}  // namespace facetlight
