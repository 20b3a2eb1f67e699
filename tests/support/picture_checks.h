#pragma once
// Checks on drawn pictures shared by the tests: colour distances, changed pixels, and what fills a facet of a
// diagram.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "image/image.h"

namespace facetlight::test {

inline double colourDistance(const Rgb& a, const Rgb& b) {
    return std::max({std::fabs(a.r - b.r), std::fabs(a.g - b.g), std::fabs(a.b - b.b)});
}

// Whether `p` lies inside a convex outline (either orientation), at least `margin` pixels from its edges.
inline bool inside(const std::vector<Point2>& outline, const Point2& p, double margin = 0) {
    double area = 0;
    for (size_t i = 0; i < outline.size(); ++i) {
        const Point2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
        area += a[0] * b[1] - b[0] * a[1];
    }
    for (size_t i = 0; i < outline.size(); ++i) {
        const Point2 &a = outline[i], &b = outline[(i + 1) % outline.size()];
        const double cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
        if (cross * (area > 0 ? 1 : -1) < margin * std::hypot(b[0] - a[0], b[1] - a[1])) return false;
    }
    return true;
}

// The pixels whose centres lie inside a convex outline, at least `margin` pixels from its edges.
inline std::vector<Rgb> pixelsInside(const Image& image, const std::vector<Point2>& outline, double margin) {
    double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
    for (const Point2& p : outline)
        x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]), y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
    std::vector<Rgb> out;
    for (int y = int(y0); y <= int(y1); ++y)
        for (int x = int(x0); x <= int(x1); ++x)
            if (inside(outline, {x + 0.5, y + 0.5}, margin)) out.push_back(image.at(x, y));
    return out;
}

// The commonest colour inside a diagram's facet: its fill, whatever label, outline or hatching lies on it.
inline Rgb fillOf(const Image& image, const std::vector<Point2>& outline) {
    std::map<std::array<int, 3>, int> count;
    for (const Rgb& c : pixelsInside(image, outline, 2))
        ++count[{int(c.r * 255 + 0.5), int(c.g * 255 + 0.5), int(c.b * 255 + 0.5)}];
    if (count.empty()) return {-1, -1, -1};
    const auto most = std::max_element(count.begin(), count.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
    return {most->first[0] / 255.0f, most->first[1] / 255.0f, most->first[2] / 255.0f};
}

// The share of a facet's inside drawn in near-black ink (hatching, dark labels).
inline double inkShare(const Image& image, const std::vector<Point2>& outline) {
    const std::vector<Rgb> pixels = pixelsInside(image, outline, 2);
    const auto dark =
        std::count_if(pixels.begin(), pixels.end(), [](const Rgb& c) { return c.r + c.g + c.b < 0.6; });
    return pixels.empty() ? 0 : double(dark) / double(pixels.size());
}

// Pixels where two pictures of the same size differ visibly.
inline std::vector<std::array<int, 2>> changedPixels(const Image& a, const Image& b) {
    std::vector<std::array<int, 2>> out;
    for (int y = 0; y < a.height(); ++y) {
        for (int x = 0; x < a.width(); ++x) {
            if (colourDistance(a.at(x, y), b.at(x, y)) > 0.05) out.push_back({x, y});
        }
    }
    return out;
}

}  // namespace facetlight::test
