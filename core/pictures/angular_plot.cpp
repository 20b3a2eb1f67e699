#include "pictures/angular_plot.h"

#include <algorithm>
#include <cmath>

#include "pictures/colormap.h"
#include "util/error.h"

namespace facetlight {

Image angularPlot(const AngularHistogram& h, const std::string& subtitle) {
    // Room above the circle for a subtitle in two lines at the legible size (scale 2, 14 px glyphs).
    constexpr int kWidth = 720, kHeight = 880;
    constexpr double kRadius = 290, cx = kWidth / 2.0, cy = 420;
    // Exits bunch into a few bright directions: a square-root colour scale keeps the faint ones visible.
    constexpr double kGamma = 0.5;
    Image image(kWidth, kHeight, {1, 1, 1});
    const Rgb ink{0.1f, 0.1f, 0.1f}, grid{0.85f, 0.85f, 0.85f};

    // Photons per steradian in each bin, relative to the busiest.
    const double dPhi = 2 * kPi / AngularHistogram::kPhiBins;
    std::vector<double> density(h.counts.size());
    double peak = 0;
    for (int t = 0; t < AngularHistogram::kThetaBins; ++t) {
        const double solidAngle = dPhi * (std::cos(radians(t)) - std::cos(radians(t + 1)));
        for (int p = 0; p < AngularHistogram::kPhiBins; ++p) {
            const size_t i = size_t(t) * AngularHistogram::kPhiBins + p;
            density[i] = double(h.counts[i]) / solidAngle;
            peak = std::max(peak, density[i]);
        }
    }
    // Each pixel of the disc looks up its bin (4 sub-samples for smooth rims).
    for (int y = int(cy - kRadius) - 1; y <= int(cy + kRadius) + 1; ++y) {
        for (int x = int(cx - kRadius) - 1; x <= int(cx + kRadius) + 1; ++x) {
            Rgb sum;
            int inside = 0;
            for (int s = 0; s < 4; ++s) {
                const double dx = x + 0.25 + 0.5 * (s & 1) - cx, dy = cy - (y + 0.25 + 0.5 * (s >> 1));
                const double r = std::hypot(dx, dy) / kRadius;
                if (r >= 1) continue;
                const int t = std::min(AngularHistogram::kThetaBins - 1, int(r * 90));
                double phi = degrees(std::atan2(dy, dx));
                if (phi < 0) phi += 360;
                const int p =
                    std::min(AngularHistogram::kPhiBins - 1, int(phi / (360.0 / AngularHistogram::kPhiBins)));
                const double v = peak > 0 ? density[size_t(t) * AngularHistogram::kPhiBins + p] / peak : 0;
                const Rgb c = viridis(std::pow(v, kGamma));
                sum.r += c.r;
                sum.g += c.g;
                sum.b += c.b;
                ++inside;
            }
            if (inside) image.blend(x, y, {sum.r / inside, sum.g / inside, sum.b / inside}, inside / 4.0f);
        }
    }
    // Rings every 30 degrees and spokes every 45, labelled outside the disc.
    for (int deg : {30, 60, 90}) {
        std::vector<Point2> ring;
        const double r = kRadius * deg / 90.0;
        for (int k = 0; k < 180; ++k)
            ring.push_back({cx + r * std::cos(k * kPi / 90), cy + r * std::sin(k * kPi / 90)});
        drawPolyline(image, ring, true, deg == 90 ? 2 : 1, deg == 90 ? ink : grid);
        // Ring labels along the 22.5-degree direction, on a white patch so they read over any colour.
        const double a = radians(22.5), lx = cx + (r + 4) * std::cos(a), ly = cy - (r + 4) * std::sin(a);
        const std::string text = std::to_string(deg) + " deg";
        const double w = textWidth(text, 2), th = textHeight(2);
        const Point2 patch[4] = {
            {lx - 2, ly - th - 4}, {lx + w + 2, ly - th - 4}, {lx + w + 2, ly}, {lx - 2, ly}};
        fillPolygon(image, patch, {1, 1, 1}, 0.85f);
        drawText(image, lx, ly - th - 2, text, 2, ink);
    }
    for (int az = 0; az < 360; az += 45) {
        const double a = radians(az), ca = std::cos(a), sa = std::sin(a);
        drawLine(image, {cx, cy}, {cx + kRadius * ca, cy - kRadius * sa}, 1, grid);
        const double lx = cx + (kRadius + 14) * ca, ly = cy - (kRadius + 14) * sa - textHeight(2) / 2;
        drawText(image, lx, ly, std::to_string(az), 2, ink,
                 std::fabs(ca) < 0.3 ? Align::Center : (ca > 0 ? Align::Left : Align::Right));
    }
    drawText(image, kWidth / 2.0, 16, "Where the light leaving the crown goes", 3, ink, Align::Center);
    const auto [first, second] = breakToFit(subtitle, 2, kWidth - 20);
    const double scale = std::max(textWidth(first, 2), textWidth(second, 2)) > kWidth - 20 ? 1.5 : 2;
    drawText(image, kWidth / 2.0, 46, first, scale, ink, Align::Center);
    if (!second.empty()) drawText(image, kWidth / 2.0, 64, second, scale, ink, Align::Center);
    drawText(image, kWidth / 2.0, second.empty() ? 66 : 84,
             "radius: angle from vertical (deg); around: azimuth (deg)", 2, ink, Align::Center);
    drawColourBar(image, 110, cy + kRadius + 50, kWidth - 220, 22, 1.0,
                  "photons per steradian, relative to the brightest direction", 2, kGamma);
    return image;
}

}  // namespace facetlight
