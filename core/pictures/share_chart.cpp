#include "pictures/share_chart.h"

#include <algorithm>
#include <cmath>

#include "util/number_text.h"

namespace facetlight {
namespace {

constexpr int kWidth = 640, kHeight = 440;
// kTop: room for the title and a subtitle of two lines (breakToFit) above the y axis's label.
constexpr double kLeft = 80, kRight = 20, kTop = 104, kBottom = 60;

}  // namespace

Image shareChart(const std::vector<SharePoint>& points, const ShareChartLabels& labels) {
    Image image(kWidth, kHeight, {1, 1, 1});
    const Rgb ink{0.1f, 0.1f, 0.1f}, grid{0.85f, 0.85f, 0.85f}, line{0.8f, 0.15f, 0.1f};
    if (points.empty()) return image;
    const double t0 = points.front().angleDeg, t1 = std::max(points.back().angleDeg, t0 + 1);
    double lo = 100, hi = 0;
    for (const SharePoint& p : points) {
        lo = std::min(lo, 100 * (p.share - p.standardError));
        hi = std::max(hi, 100 * (p.share + p.standardError));
    }
    // Whole 5 % steps around the data.
    lo = std::max(0.0, 5 * std::floor(lo / 5 - 1e-9));
    hi = std::min(100.0, std::max(lo + 5, 5 * std::ceil(hi / 5 + 1e-9)));
    const double plotW = kWidth - kLeft - kRight, plotH = kHeight - kTop - kBottom;
    auto px = [&](double t) { return kLeft + (t - t0) / (t1 - t0) * plotW; };
    auto py = [&](double pct) { return kTop + (hi - pct) / (hi - lo) * plotH; };

    const double yStep = hi - lo > 20 ? 10 : (hi - lo > 10 ? 5 : 1);
    for (double v = lo; v <= hi + 1e-9; v += yStep) {
        drawLine(image, {kLeft, py(v)}, {kLeft + plotW, py(v)}, 1, grid);
        drawText(image, kLeft - 8, py(v) - textHeight(2) / 2, formatNumber("%g", v), 2, ink, Align::Right);
    }
    // Labels of up to three digits a tick apart: 30 deg steps over more than 120 deg.
    const double span = t1 - t0, xStep = span > 120 ? 30 : span > 40 ? 10 : (span > 10 ? 5 : 1);
    for (double t = std::ceil(t0 / xStep) * xStep; t <= t1 + 1e-9; t += xStep) {
        drawLine(image, {px(t), kTop}, {px(t), kTop + plotH}, 1, grid);
        drawText(image, px(t), kTop + plotH + 6, formatNumber("%g", t), 2, ink, Align::Center);
    }
    drawPolyline(
        image,
        std::vector<Point2>{
            {kLeft, kTop}, {kLeft + plotW, kTop}, {kLeft + plotW, kTop + plotH}, {kLeft, kTop + plotH}},
        true, 1, ink);

    std::vector<Point2> curve;
    for (const SharePoint& f : points) {
        const double x = px(f.angleDeg), v = 100 * f.share, e = 100 * f.standardError;
        curve.push_back({x, py(v)});
        drawLine(image, {x, py(v - e)}, {x, py(v + e)}, 1.5, ink);
    }
    drawPolyline(image, curve, false, 2, line);
    for (const Point2& p : curve) {
        const Point2 dot[4] = {{p[0] - 3, p[1]}, {p[0], p[1] - 3}, {p[0] + 3, p[1]}, {p[0], p[1] + 3}};
        fillPolygon(image, dot, line);
    }

    // The title on its line as large as fits, up to 2.5 (1.5 ran a long stone name off both edges).
    const std::string& title = labels.title;
    drawText(image, kWidth / 2.0, 10, title,
             std::min(2.5, (kWidth - 10) / std::max(1.0, textWidth(title, 1))), ink, Align::Center);
    // The subtitle in up to two lines at the legible size, or else smaller.
    double scale = 2;
    std::vector<std::string> lines = wrapToFit(labels.subtitle, scale, kWidth - 10);
    if (lines.size() > 2) lines = wrapToFit(labels.subtitle, scale = 1.5, kWidth - 10);
    for (size_t k = 0; k < std::min<size_t>(lines.size(), 2); ++k)
        drawText(image, kWidth / 2.0, 40 + 17 * double(k), lines[k], scale, ink, Align::Center);
    drawText(image, kLeft + plotW / 2, kHeight - 24, labels.across, 2, ink, Align::Center);
    drawText(image, 8, kTop - 26, labels.up, 2, ink);
    return image;
}

}  // namespace facetlight
