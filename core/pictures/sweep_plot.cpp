#include "pictures/sweep_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "pictures/colormap.h"
#include "util/error.h"

namespace facetlight {
namespace {

const Rgb kInk{0.1f, 0.1f, 0.1f};
const Rgb kWhite{1, 1, 1};
// Tableau 10's first colours: distinct, and distinct in grey.
const std::array<Rgb, 6> kSeriesColours{Rgb{0.12f, 0.47f, 0.71f}, Rgb{1.0f, 0.5f, 0.05f},
                                        Rgb{0.17f, 0.63f, 0.17f}, Rgb{0.84f, 0.15f, 0.16f},
                                        Rgb{0.58f, 0.4f, 0.74f},  Rgb{0.55f, 0.34f, 0.29f}};
constexpr int kContourBands = 12;

struct Range {
    double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
    void add(double v) { lo = std::min(lo, v), hi = std::max(hi, v); }
    // Widened by `share` of its span on each side; a single value gets +-`minimum`.
    Range padded(double share, double minimum) const {
        const double pad = hi > lo ? share * (hi - lo) : std::max(minimum, std::fabs(lo) * 0.05);
        return {lo - pad, hi + pad};
    }
};

// Where the data of an axis lie: numbers span their values; categories are cells around 0, 1, ...
Range axisRange(const PlotAxis& axis) {
    Range r;
    if (!axis.choices.empty() || axis.size() < 2) {
        for (size_t i = 0; i < axis.size(); ++i) r.add(axis.position(i));
        return {r.lo - 0.5, r.hi + 0.5};
    }
    for (double v : axis.values) r.add(v);
    return r;
}

// Round values inside [lo, hi], about five, 1, 2 or 5 times a power of 10 apart.
std::vector<double> rangeTicks(const Range& r, double& step) {
    niceTicks(r.hi - r.lo, step);
    std::vector<double> ticks;
    const double first = std::ceil(r.lo / step - 1e-9) * step;
    for (int i = 0; first + i * step <= r.hi + 1e-9 * step; ++i) {
        const double t = first + i * step;
        ticks.push_back(std::fabs(t) < 1e-12 * step ? 0.0 : t);
    }
    return ticks;
}

// A plot's frame: the pixel rectangle and the data ranges it shows.
struct Frame {
    double left, top, right, bottom;
    Range x, y;
    double px(double v) const { return left + (v - x.lo) / (x.hi - x.lo) * (right - left); }
    double py(double v) const { return bottom - (v - y.lo) / (y.hi - y.lo) * (bottom - top); }
};

void drawTicks(Image& image, const Frame& f, const PlotAxis& axis, bool horizontal) {
    std::vector<std::pair<double, std::string>> ticks;
    if (!axis.choices.empty()) {
        for (size_t i = 0; i < axis.size(); ++i) ticks.push_back({double(i), axis.choices[i]});
    } else {
        double step;
        for (double t : rangeTicks(horizontal ? f.x : f.y, step)) ticks.push_back({t, tickLabel(t, step)});
    }
    for (const auto& [v, label] : ticks) {
        if (horizontal) {
            const double x = f.px(v);
            drawLine(image, {x, f.bottom}, {x, f.bottom + 6}, 1.5, kInk);
            drawText(image, x, f.bottom + 10, label, 2, kInk, Align::Center);
        } else {
            const double y = f.py(v);
            drawLine(image, {f.left - 6, y}, {f.left, y}, 1.5, kInk);
            drawText(image, f.left - 10, y - textHeight(2) / 2, label, 2, kInk, Align::Right);
        }
    }
}

// The frame's box, ticks and axis labels, and the title above.
void drawAxes(Image& image, const Frame& f, const PlotAxis& x, const PlotAxis& y, const std::string& title) {
    const Point2 box[4] = {{f.left, f.top}, {f.right, f.top}, {f.right, f.bottom}, {f.left, f.bottom}};
    drawPolyline(image, box, true, 1.5, kInk);
    drawTicks(image, f, x, true);
    drawTicks(image, f, y, false);
    drawText(image, (f.left + f.right) / 2, f.bottom + 36, x.label, 2.2, kInk, Align::Center);
    drawText(image, f.left - 60, f.top - 28, y.label, 2.2, kInk);
    // A long title (the held parameters and the highest point) is drawn smaller rather than cut at the edges.
    const double scale = std::min(2.2, (image.width() - 20) / textWidth(title, 1.0));
    drawText(image, image.width() / 2.0, 12, title, scale, kInk, Align::Center);
}

// A label on a white patch, readable on any background.
void drawLabel(Image& image, double x, double y, const std::string& text) {
    const double w = textWidth(text, 1.8), h = textHeight(1.8);
    const Point2 patch[4] = {{x - 3, y - 3}, {x + w + 3, y - 3}, {x + w + 3, y + h + 1}, {x - 3, y + h + 1}};
    fillPolygon(image, patch, kWhite, 0.8f);
    drawText(image, x, y, text, 1.8, kInk);
}

void drawMarker(Image& image, double x, double y, bool best) {
    if (best) {
        std::vector<Point2> star;
        for (int k = 0; k < 10; ++k) {
            const double a = k * M_PI / 5 - M_PI / 2, r = k % 2 ? 5.0 : 12.0;
            star.push_back({x + r * std::cos(a), y + r * std::sin(a)});
        }
        fillPolygon(image, star, kWhite);
        drawPolyline(image, star, true, 1.5, kInk);
        return;
    }
    std::vector<Point2> ring;
    for (int k = 0; k < 24; ++k)
        ring.push_back({x + 7 * std::cos(k * M_PI / 12), y + 7 * std::sin(k * M_PI / 12)});
    drawPolyline(image, ring, true, 3.5, kWhite);
    drawPolyline(image, ring, true, 1.8, kInk);
}

// The node below x on the axis and the fraction of the way to the next (categories: the nearest, fraction 0).
std::pair<size_t, double> locate(const PlotAxis& axis, double x) {
    if (!axis.choices.empty() || axis.size() < 2)
        return {size_t(std::clamp(std::lround(x), 0L, long(axis.size()) - 1)), 0.0};
    const auto it = std::upper_bound(axis.values.begin(), axis.values.end(), x);
    const size_t i = std::min<size_t>(std::max<ptrdiff_t>(it - axis.values.begin() - 1, 0), axis.size() - 2);
    const double t = (x - axis.values[i]) / (axis.values[i + 1] - axis.values[i]);
    return {i, std::clamp(t, 0.0, 1.0)};
}

}  // namespace

Image seriesPlot(const PlotAxis& x, const std::vector<PlotSeries>& series, const std::string& yLabel,
                 const std::string& title) {
    Image image(900, 600, kWhite);
    Range yr;
    for (const PlotSeries& s : series)
        for (size_t i = 0; i < s.value.size(); ++i)
            if (s.valid[i]) yr.add(s.value[i] - s.sigma[i]), yr.add(s.value[i] + s.sigma[i]);
    if (!(yr.lo <= yr.hi)) yr = {0, 1};
    const Frame f{110, 80, 870, 480, axisRange(x), yr.padded(0.06, 1e-3)};
    const PlotAxis y{yLabel, {}, {}};

    for (size_t k = 0; k < series.size(); ++k) {
        const PlotSeries& s = series[k];
        const Rgb colour = kSeriesColours[k % kSeriesColours.size()];
        // Each run of valid points: a band, a line, a dot per point (and an error bar where a run is one
        // point).
        for (size_t i = 0; i < x.size();) {
            if (!s.valid[i]) {
                ++i;
                continue;
            }
            size_t end = i;
            while (end < x.size() && s.valid[end]) ++end;
            std::vector<Point2> band, line;
            for (size_t j = i; j < end; ++j) {
                band.push_back({f.px(x.position(j)), f.py(s.value[j] + s.sigma[j])});
                line.push_back({f.px(x.position(j)), f.py(s.value[j])});
            }
            for (size_t j = end; j-- > i;)
                band.push_back({f.px(x.position(j)), f.py(s.value[j] - s.sigma[j])});
            if (end - i > 1) {
                fillPolygon(image, band, colour, 0.3f);
                drawPolyline(image, line, false, 2.2, colour);
            } else {
                drawLine(image, band[0], band[1], 2, colour);
            }
            for (const Point2& p : line) {
                const Point2 dot[4] = {
                    {p[0] - 3, p[1]}, {p[0], p[1] - 3}, {p[0] + 3, p[1]}, {p[0], p[1] + 3}};
                fillPolygon(image, dot, colour);
            }
            i = end;
        }
    }
    drawAxes(image, f, x, y, title);

    // The legend: a swatch of line and band for each series, then what the band means.
    double lx = f.left;
    const double ly = f.bottom + 80;
    for (size_t k = 0; k < series.size(); ++k) {
        const Rgb colour = kSeriesColours[k % kSeriesColours.size()];
        const Point2 swatch[4] = {{lx, ly - 8}, {lx + 36, ly - 8}, {lx + 36, ly + 8}, {lx, ly + 8}};
        fillPolygon(image, swatch, colour, 0.3f);
        drawLine(image, {lx, ly}, {lx + 36, ly}, 2.2, colour);
        drawText(image, lx + 44, ly - textHeight(2) / 2, series[k].name, 2, kInk);
        lx += 44 + textWidth(series[k].name, 2) + 30;
    }
    drawText(image, f.left, ly + 24, "lines: the figure at each point; bands: +-1 standard error", 1.8, kInk);
    return image;
}

Image contourMap(const PlotAxis& x, const PlotAxis& y, const PlotSeries& grid, const std::string& valueLabel,
                 const std::vector<PlotMarker>& markers, const std::string& title) {
    if (grid.value.size() != x.size() * y.size() || grid.valid.size() != grid.value.size())
        throw Error("contour map: the grid does not match its axes");
    Image image(900, 720, kWhite);
    // Room on the left for the longest category name.
    double names = 0;
    for (const std::string& c : y.choices) names = std::max(names, textWidth(c, 2));
    const Frame f{std::max(110.0, names + 24), 80, 740, 590, axisRange(x), axisRange(y)};
    Range vr;
    for (size_t k = 0; k < grid.value.size(); ++k)
        if (grid.valid[k]) vr.add(grid.value[k]);
    if (!(vr.lo < vr.hi)) vr = vr.lo <= vr.hi ? vr.padded(0, 1e-3) : Range{0, 1};
    const auto band = [&](double v) {
        return std::clamp(int((v - vr.lo) / (vr.hi - vr.lo) * kContourBands), 0, kContourBands - 1);
    };
    const auto bandColour = [](int b) { return viridis((b + 0.5) / kContourBands); };

    const Rgb missing{0.75f, 0.75f, 0.75f};
    for (int py = int(f.top); py < int(f.bottom); ++py) {
        const double yv = f.y.lo + (f.bottom - (py + 0.5)) / (f.bottom - f.top) * (f.y.hi - f.y.lo);
        const auto [j, ty] = locate(y, yv);
        for (int px = int(f.left); px < int(f.right); ++px) {
            const double xv = f.x.lo + (px + 0.5 - f.left) / (f.right - f.left) * (f.x.hi - f.x.lo);
            const auto [i, tx] = locate(x, xv);
            const size_t i1 = std::min(i + 1, x.size() - 1), j1 = std::min(j + 1, y.size() - 1);
            const size_t nodes[4] = {i * y.size() + j, i1 * y.size() + j, i * y.size() + j1,
                                     i1 * y.size() + j1};
            const double w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
            double v = 0;
            bool ok = true;
            for (int n = 0; n < 4; ++n) {
                if (w[n] == 0) continue;
                ok = ok && grid.valid[nodes[n]];
                v += w[n] * grid.value[nodes[n]];
            }
            image.at(px, py) = ok ? bandColour(band(v)) : missing;
        }
    }
    // The nodes that were traced, faintly.
    if (grid.value.size() <= 2500)
        for (size_t i = 0; i < x.size(); ++i)
            for (size_t j = 0; j < y.size(); ++j) {
                const double cx = f.px(x.position(i)), cy = f.py(y.position(j));
                const Point2 dot[4] = {{cx - 1.2, cy}, {cx, cy - 1.2}, {cx + 1.2, cy}, {cx, cy + 1.2}};
                fillPolygon(image, dot, kInk, 0.35f);
            }
    bool references = false;
    for (const PlotMarker& m : markers) {
        if (m.x < f.x.lo || m.x > f.x.hi || m.y < f.y.lo || m.y > f.y.hi) continue;
        references = references || !m.best;
        const double cx = f.px(m.x), cy = f.py(m.y);
        drawMarker(image, cx, cy, m.best);
        const double w = textWidth(m.label, 1.8);
        // Right of the marker, kept inside the frame; the best point's label above it, or below near the top.
        const double lx = std::clamp(cx + 14, f.left + 4, f.right - w - 4);
        const double ly = m.best ? (cy - 30 > f.top ? cy - 30 : cy + 16) : cy + 6;
        drawLabel(image, lx, ly, m.label);
    }
    drawAxes(image, f, x, y, title);

    // The colour scale: the bands as drawn, with round values marked.
    const double bx = 780, bw = 28;
    for (int b = 0; b < kContourBands; ++b) {
        const double y0 = f.bottom - (f.bottom - f.top) * b / kContourBands,
                     y1 = f.bottom - (f.bottom - f.top) * (b + 1) / kContourBands;
        const Point2 cell[4] = {{bx, y0}, {bx + bw, y0}, {bx + bw, y1}, {bx, y1}};
        fillPolygon(image, cell, bandColour(b));
    }
    const Point2 barBox[4] = {{bx, f.top}, {bx + bw, f.top}, {bx + bw, f.bottom}, {bx, f.bottom}};
    drawPolyline(image, barBox, true, 1.2, kInk);
    double step;
    for (double t : rangeTicks(vr, step)) {
        const double ty = f.bottom - (t - vr.lo) / (vr.hi - vr.lo) * (f.bottom - f.top);
        drawLine(image, {bx + bw, ty}, {bx + bw + 6, ty}, 1.5, kInk);
        drawText(image, bx + bw + 9, ty - textHeight(1.8) / 2, tickLabel(t, step), 1.8, kInk);
    }
    drawText(image, bx + bw / 2, f.top - 28, "colour", 2, kInk, Align::Center);
    drawText(image, f.left, f.bottom + 74,
             "colour: " + valueLabel + ", " + std::to_string(kContourBands) +
                 " bands from lowest to highest point",
             1.8, kInk);
    const bool gaps = std::find(grid.valid.begin(), grid.valid.end(), false) != grid.valid.end();
    drawText(image, f.left, f.bottom + 96,
             std::string("star: highest point") + (references ? "; rings: reference designs" : "") +
                 "; dots: points traced" + (gaps ? "; grey: no stone" : ""),
             1.8, kInk);
    return image;
}

}  // namespace facetlight
