#include "heatmap.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "colormap.h"
#include "error.h"

namespace facetlight {
namespace {

std::string percent(double share, int decimals) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f%%", decimals, 100 * share);
    return buffer;
}

}  // namespace

Image facetHeatmap(const Stone& stone, const FacetStats& stats) {
    if (stats.facets.size() != stone.facets.size())
        throw Error("statistics do not belong to stone '" + stone.name + "'");
    constexpr int kWidth = 1100, kHeight = 720;
    constexpr double kHalf = 230;  // pixels from a diagram's centre to the stone's widest point
    const double centres[2][2] = {{kWidth * 0.25 + 5, 330}, {kWidth * 0.75 - 5, 330}};
    Image image(kWidth, kHeight, {1, 1, 1});
    const Rgb ink{0.1f, 0.1f, 0.1f};

    double extent = 0;
    for (const Vec3& v : stone.vertices) extent = std::max({extent, std::fabs(v.x), std::fabs(v.y)});
    if (!(extent > 0)) extent = 1;
    const double hit = double(std::max<uint64_t>(stats.hit, 1));
    auto shareOf = [&](size_t f) { return double(stats.facets[f].leaving) / hit; };
    double maxShare = 0;
    for (size_t f = 0; f < stone.facets.size(); ++f) maxShare = std::max(maxShare, shareOf(f));
    // The colour scale ends on the colour bar's first tick at or above the largest share.
    double step;
    niceTicks(100 * maxShare, step);
    const double barMax = std::ceil(100 * maxShare / step - 1e-9) * step / 100;

    // side 0: table and crown from above; side 1: pavilion from below (mirrored in x, as when turned over
    // about the y axis). Facets are drawn far side first so that the near ones cover them.
    auto onSide = [&](const Facet& f, int side) {
        return side == 0 ? (f.region == Region::Table || f.region == Region::Crown)
                         : f.region == Region::Pavilion;
    };
    auto project = [&](const Vec3& v, int side) -> Point2 {
        const double x = side == 0 ? v.x : -v.x;
        return {centres[side][0] + x / extent * kHalf, centres[side][1] - v.y / extent * kHalf};
    };
    for (int side = 0; side < 2; ++side) {
        std::vector<size_t> order;
        for (size_t f = 0; f < stone.facets.size(); ++f) {
            if (onSide(stone.facets[f], side)) order.push_back(f);
        }
        std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
            const double za = stone.facets[a].centroid.z, zb = stone.facets[b].centroid.z;
            return side == 0 ? za < zb : za > zb;
        });
        std::vector<Point2> outline;
        for (size_t f : order) {
            outline.clear();
            for (uint32_t v : stone.facets[f].outline) outline.push_back(project(stone.vertices[v], side));
            fillPolygon(image, outline, viridis(barMax > 0 ? shareOf(f) / barMax : 0));
            drawPolyline(image, outline, true, 1.2, ink);
        }
        // The busiest facets of this side, labelled with their shares.
        std::vector<size_t> busiest = order;
        std::sort(busiest.begin(), busiest.end(),
                  [&](size_t a, size_t b) { return shareOf(a) > shareOf(b); });
        busiest.resize(std::min<size_t>(busiest.size(), 8));
        for (size_t f : busiest) {
            if (stats.facets[f].leaving == 0) continue;
            const Point2 c = project(stone.facets[f].centroid, side);
            const double t = barMax > 0 ? shareOf(f) / barMax : 0;
            drawText(image, c[0], c[1] - textHeight(1.5) / 2, percent(shareOf(f), 1), 1.5, contrastOn(t),
                     Align::Center);
        }
        const char* title = side == 0 ? "Crown and table, from above" : "Pavilion, from below";
        drawText(image, centres[side][0], 78, title, 2.5, ink, Align::Center);
    }

    drawText(image, kWidth / 2.0, 14, "Share of the light leaving through each facet", 3, ink, Align::Center);
    std::array<double, kRegionCount> regionShare{};
    for (size_t f = 0; f < stone.facets.size(); ++f)
        regionShare[size_t(stone.facets[f].region)] += shareOf(f);
    const std::string summary = "of the photons hitting the stone (" + std::to_string(stats.hit) +
                                "): table " + percent(regionShare[size_t(Region::Table)], 1) + ", crown " +
                                percent(regionShare[size_t(Region::Crown)], 1) + ", pavilion " +
                                percent(regionShare[size_t(Region::Pavilion)], 1) + ", girdle " +
                                percent(regionShare[size_t(Region::Girdle)], 1);
    drawText(image, kWidth / 2.0, 48, summary, 2, ink, Align::Center);
    drawColourBar(image, 200, kHeight - 110, kWidth - 400, 24, barMax > 0 ? 100 * barMax : 1,
                  "share of the light leaving through the facet (%)", 2);
    return image;
}

}  // namespace facetlight
