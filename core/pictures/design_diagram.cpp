#include "pictures/design_diagram.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "io/gemcad_design.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

constexpr int kWidth = 1400;
constexpr double kHalf = 190;  // pixels from a view's centre to the stone's widest point
constexpr double kViewTop = 90, kViewCentre = kViewTop + 50 + kHalf;  // titles, index marks, then the views
// The sheet under the views: its heading, then a row a tier in up to two columns of at most kRowsPerColumn.
constexpr double kSheetTop = kViewCentre + kHalf + 64, kRowHeight = 20;
constexpr size_t kRowsPerColumn = 16;
const Rgb kPaper{1, 1, 1}, kInk{0.1f, 0.1f, 0.12f}, kFaint{0.45f, 0.45f, 0.5f};
const Rgb kCrownFill{0.86f, 0.92f, 0.98f}, kPavilionFill{0.93f, 0.9f, 0.98f}, kGirdleFill{0.9f, 0.9f, 0.9f};

struct View {
    std::string title;
    Point2 centre;
    std::function<Point2(const Vec3&)> project;  // relative to the centre, pixels per unit applied
    std::function<bool(const Facet&)> shows;
    std::function<double(const Facet&)> depth;  // drawn far first
};

void drawView(Image& image, const Stone& stone, const View& view, double unit) {
    drawText(image, view.centre[0], kViewTop, view.title, 2.2, kInk, Align::Center);
    std::vector<const Facet*> facets;
    for (const Facet& f : stone.facets)
        if (view.shows(f)) facets.push_back(&f);
    std::sort(facets.begin(), facets.end(),
              [&](const Facet* a, const Facet* b) { return view.depth(*a) < view.depth(*b); });
    auto at = [&](const Vec3& v) {
        const Point2 p = view.project(v);
        return Point2{view.centre[0] + p[0] * unit, view.centre[1] + p[1] * unit};
    };
    for (const Facet* f : facets) {
        std::vector<Point2> outline;
        for (uint32_t v : f->outline) outline.push_back(at(stone.vertices[v]));
        const Rgb fill = f->region == Region::Pavilion ? kPavilionFill
                         : f->region == Region::Girdle ? kGirdleFill
                                                       : kCrownFill;
        fillPolygon(image, outline, fill);
        drawPolyline(image, outline, true, 1.4, kInk);
    }
    // Labels where a facet shows enough of itself to hold one.
    for (const Facet* f : facets) {
        std::vector<Point2> outline;
        double area = 0;
        for (uint32_t v : f->outline) outline.push_back(at(stone.vertices[v]));
        for (size_t i = 0; i < outline.size(); ++i) {
            const Point2& a = outline[i];
            const Point2& b = outline[(i + 1) % outline.size()];
            area += a[0] * b[1] - b[0] * a[1];
        }
        const std::string label = facetNameStem(f->name);
        const double scale = 1.4;
        if (std::fabs(area) / 2 < 2.2 * textWidth(label, scale) * textHeight(scale)) continue;
        const Point2 c = at(f->centroid);
        drawText(image, c[0], c[1] - textHeight(scale) / 2, label, scale, kInk, Align::Center);
    }
}

}  // namespace

Image designDiagram(const Stone& stone, const std::optional<CuttingSheet>& sheet, const StoneSize& size) {
    // As tall as the sheet needs: two columns once one would run past kRowsPerColumn.
    const size_t tiers = sheet ? sheet->tiers.size() : 0;
    const size_t perColumn = std::min(kRowsPerColumn, tiers > kRowsPerColumn ? (tiers + 1) / 2 : tiers);
    const int height = int(kSheetTop + 30 + kRowHeight * double(perColumn + (tiers > 2 * perColumn)) + 16);
    Image image(kWidth, height, kPaper);
    double extent = 0;
    for (const Vec3& v : stone.vertices) extent = std::max({extent, std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)});
    const double unit = kHalf / (extent > 0 ? extent : 1);
    const double top = kViewCentre;
    const View views[3] = {
        {"crown (from above)", {230, top}, [](const Vec3& v) { return Point2{v.x, -v.y}; },
         [](const Facet& f) { return f.normal.z > 1e-9; }, [](const Facet& f) { return f.centroid.z; }},
        {"profile (from the front, -y)", {660, top}, [](const Vec3& v) { return Point2{v.x, -v.z}; },
         [](const Facet& f) { return f.normal.y < -1e-9; }, [](const Facet& f) { return -f.centroid.y; }},
        // From below, as when the stone is turned over about the y axis: x mirrored.
        {"pavilion (from below)", {1090, top}, [](const Vec3& v) { return Point2{-v.x, -v.y}; },
         [](const Facet& f) { return f.normal.z < -1e-9; }, [](const Facet& f) { return -f.centroid.z; }},
    };
    for (const View& view : views) drawView(image, stone, view, unit);
    // Where index 0 of the gear points (+y unless the design turns its gear), on the crown and pavilion views.
    const double zeroDeg = sheet ? 360.0 * (0 - sheet->gearOffset) / sheet->gear : 0.0;
    const double sx = std::sin(radians(zeroDeg)), sy = std::cos(radians(zeroDeg));
    for (const auto& [x, mirrored] : {std::pair{230.0, false}, std::pair{1090.0, true}}) {
        const double dx = mirrored ? -sx : sx;
        const Point2 a{x + dx * (kHalf + 6), top - sy * (kHalf + 6)}, b{x + dx * (kHalf + 22), top - sy * (kHalf + 22)};
        drawLine(image, a, b, 2, kFaint);
        // Beside the mark's outer end, clear of the view's title above it.
        drawText(image, b[0] + (dx >= 0 ? 6 : -6), b[1] - 5, "index " + std::to_string(std::abs(sheet ? sheet->gear : 96)),
                 1.3, kFaint, dx >= 0 ? Align::Left : Align::Right);
    }
    // A scale bar of 1 mm (or 5 mm on a large stone) under the profile.
    const double mm = size.lengthMm > 0 ? stone.proportions.length / size.lengthMm : 0;
    if (mm > 0) {
        const double bar = size.lengthMm > 20 ? 5 : 1, px = bar * mm * unit;
        drawLine(image, {660 - px / 2, top + kHalf + 22}, {660 + px / 2, top + kHalf + 22}, 3, kInk);
        drawText(image, 660, top + kHalf + 30, formatNumber("%g mm", bar), 1.6, kInk, Align::Center);
    }

    // Title and the sheet's tiers.
    std::string title = stone.name;
    if (sheet && !sheet->headers.empty()) title += ": " + sheet->headers.front();
    if (title.size() > 110) title = title.substr(0, 107) + "...";
    drawText(image, 30, 18, title, 2.6, kInk);
    std::string sizes = formatNumber("%.2f", size.lengthMm) + " x " + formatNumber("%.2f", size.widthMm) + " x " +
                        formatNumber("%.2f mm", size.depthMm) + ", " + std::to_string(stone.facets.size()) +
                        " facets";
    if (size.carats) sizes += ", " + formatNumber("%.2f ct", *size.carats);
    drawText(image, 30, 52, sizes, 1.8, kFaint);
    if (!sheet) return image;
    std::string head = std::to_string(std::abs(sheet->gear)) + "-tooth gear, " + std::to_string(sheet->symmetry) +
                       "-fold" + (sheet->mirror ? " mirror" : "") + " symmetry";
    if (sheet->refractiveIndex) head += ", index " + formatNumber("%.3f", *sheet->refractiveIndex);
    drawText(image, 30, kSheetTop, head, 1.8, kInk);
    const double y = kSheetTop + 30;
    size_t row = 0;
    for (const SheetTier& t : sheet->tiers) {
        const double x = 30 + double(row / perColumn) * 690;
        const double yy = y + double(row % perColumn) * kRowHeight;
        std::string indices;
        for (double i : t.indices) indices += (indices.empty() ? "" : "-") + gearIndexText(i, sheet->gear);
        if (indices.size() > 58) indices = indices.substr(0, 55) + "...";
        std::string line = t.name + "  " + (std::signbit(t.angleDeg) ? "P " : "C ") +
                           formatNumber("%.2f", std::fabs(t.angleDeg)) + "  " + indices;
        drawText(image, x, yy, line, 1.6, kInk);
        if (++row >= 2 * perColumn && row < tiers) {
            drawText(image, x, yy + kRowHeight, "... (the full sheet: stats.json cutting_sheet)", 1.4, kFaint);
            break;
        }
    }
    return image;
}

}  // namespace facetlight
