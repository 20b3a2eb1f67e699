#include "pictures/heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "pictures/colormap.h"
#include "util/error.h"

namespace facetlight {
namespace {

std::string percent(double share, int decimals) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f%%", decimals, 100 * share);
    return buffer;
}

constexpr int kWidth = 1100, kHeight = 720;
constexpr Point2 kCentre[2] = {{kWidth * 0.25 + 5, 330}, {kWidth * 0.75 - 5, 330}};

}  // namespace

HeatmapLayout heatmapLayout(const Stone& stone) {
    constexpr double kHalf = 230;  // pixels from a diagram's centre to the stone's widest point
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

// The facet diagram of `share` (one per facet, in [0, 1]); facets of zero share stay unlabelled.
Image shareHeatmap(const Stone& stone, const std::vector<double>& share, const ShareWording& words) {
    const HeatmapLayout layout = heatmapLayout(stone);
    Image image(layout.width, layout.height, {1, 1, 1});
    const Rgb ink{0.1f, 0.1f, 0.1f};

    const double maxShare = *std::max_element(share.begin(), share.end());
    // The colour scale ends on the colour bar's first tick at or above the largest share.
    double step;
    niceTicks(100 * maxShare, step);
    const double barMax = std::ceil(100 * maxShare / step - 1e-9) * step / 100;

    for (int side = 0; side < 2; ++side) {
        std::vector<const HeatmapFacet*> order;
        for (const HeatmapFacet& f : layout.facets) {
            if (f.side != side) continue;
            order.push_back(&f);
            fillPolygon(image, f.outline, viridis(barMax > 0 ? share[f.facet] / barMax : 0));
            drawPolyline(image, f.outline, true, 1.2, ink);
        }
        // The busiest facets of this side, labelled with their shares.
        std::vector<const HeatmapFacet*> busiest = order;
        std::sort(busiest.begin(), busiest.end(), [&](const HeatmapFacet* a, const HeatmapFacet* b) {
            return share[a->facet] > share[b->facet];
        });
        busiest.resize(std::min<size_t>(busiest.size(), 8));
        for (const HeatmapFacet* f : busiest) {
            if (share[f->facet] == 0) continue;
            const double t = barMax > 0 ? share[f->facet] / barMax : 0;
            drawText(image, f->centroid[0], f->centroid[1] - textHeight(1.5) / 2, percent(share[f->facet], 1),
                     1.5, contrastOn(t), Align::Center);
        }
        const char* title = side == 0 ? "Crown and table, from above" : "Pavilion, from below";
        drawText(image, kCentre[side][0], 78, title, 2.5, ink, Align::Center);
    }

    drawText(image, kWidth / 2.0, 14, words.title, 3, ink, Align::Center);
    std::array<double, kRegionCount> regionShare{};
    for (size_t f = 0; f < stone.facets.size(); ++f) regionShare[size_t(stone.facets[f].region)] += share[f];
    const std::string summary = words.whole + ": table " + percent(regionShare[size_t(Region::Table)], 1) +
                                ", crown " + percent(regionShare[size_t(Region::Crown)], 1) + ", pavilion " +
                                percent(regionShare[size_t(Region::Pavilion)], 1) + ", girdle " +
                                percent(regionShare[size_t(Region::Girdle)], 1);
    drawText(image, kWidth / 2.0, 48, summary, 2, ink, Align::Center);
    drawColourBar(image, 200, kHeight - 110, kWidth - 400, 24, barMax > 0 ? 100 * barMax : 1, words.bar, 2);
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
