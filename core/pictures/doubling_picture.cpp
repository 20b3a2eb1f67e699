#include "pictures/doubling_picture.h"

#include <algorithm>
#include <cmath>

#include "scene/scene.h"

#include "pictures/face_up_frame.h"
#include "util/number_text.h"

namespace facetlight {
namespace {

const Rgb kInk{0.1f, 0.1f, 0.1f};
const Rgb kOrdinary{0.1f, 0.3f, 0.95f};
const Rgb kExtraordinary{0.95f, 0.35f, 0.05f};
const Rgb kBoth{0.45f, 0.1f, 0.55f};
const Rgb kCrownEdge{0.35f, 0.35f, 0.35f};

std::string mm(double v) {
    return formatNumber(v < 0.1 ? "%.3f" : "%.2f", v);
}

}  // namespace

std::string doublingTitle(const Stone& stone, const TraceSettings& settings) {
    const Material material = chooseMaterial(settings, stone).material;
    const OpticAxisSettings& axis = settings.opticAxis;
    const bool biaxial = material.optic() == Optic::Biaxial;
    return "Doubling: " + stone.name + ", " + material.name() + (biaxial ? ", Z axis " : ", optic axis ") +
           formatNumber("%g", axis.tiltDeg) + " deg from the table's normal toward " +
           formatNumber("%g", axis.azimuthDeg) + " deg" +
           (biaxial ? ", X turned " + formatNumber("%g", axis.rotationDeg) + " deg" : "");
}

std::string doublingSummary(const Doubling& d) {
    if (!d.doublyRefracting) return "no doubling: " + d.tracedAs;
    const DoublingSpread& t = d.table;
    return "through the table: median " + mm(t.medianMm) + " mm (quartiles " + mm(t.lowMm) + "-" +
           mm(t.highMm) + "), " + formatNumber("%.2f", 100 * d.shareOfDiameter(t.medianMm)) +
           " % of the girdle, " + formatNumber("%.1f", d.arcMinutes(t.medianMm)) + " arcmin through a " +
           formatNumber("%g", d.loupe) + "x loupe; through the whole crown: median " + mm(d.crown.medianMm) +
           " mm (quartiles " + mm(d.crown.lowMm) + "-" + mm(d.crown.highMm) + "), seen " +
           formatNumber("%.0f", d.viewToAxisDeg) +
           (d.nA > 0 ? " deg from the nearer optic axis" : " deg from the optic axis");
}

Image doublingPicture(const Doubling& d, const std::string& title) {
    const int n = d.size, s = std::max(1, 480 / std::max(n, 1)), side = n * s;
    const int width = std::max(side + 20, 720);
    const TitleBlock head = titleBlock(title, doublingSummary(d), width);
    Image image(width, head.height() + side + 10 + kScaleBarHeight + 3 * kLegendLineStep + 12, {1, 1, 1});
    const int left = (width - side) / 2, top = head.height();
    auto at = [&](const std::vector<int32_t>& v, int x, int y) {
        return v[size_t(y) * size_t(n) + size_t(x)];
    };
    // An edge where a pixel's facet differs from its right or lower neighbour's, both on the stone.
    auto edge = [&](const std::vector<int32_t>& v, int x, int y) {
        if (at(d.entry, x, y) < 0) return false;
        const bool right = x + 1 < n && at(d.entry, x + 1, y) >= 0 && at(v, x + 1, y) != at(v, x, y);
        const bool down = y + 1 < n && at(d.entry, x, y + 1) >= 0 && at(v, x, y + 1) != at(v, x, y);
        return right || down;
    };
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const int entry = at(d.entry, x, y);
            if (entry < 0) continue;
            Rgb c{0.78f, 0.78f, 0.78f};
            const bool o = edge(d.ordinary, x, y), e = edge(d.extraordinary, x, y);
            if (o && e) {
                c = kBoth;
            } else if (o) {
                c = kOrdinary;
            } else if (e) {
                c = kExtraordinary;
            } else if (edge(d.entry, x, y)) {
                c = kCrownEdge;
            } else if (at(d.ordinary, x, y) < 0) {
                c = {0.62f, 0.62f, 0.62f};  // the ordinary wave meets the girdle or the crown first
            }
            for (int dy = 0; dy < s; ++dy)
                for (int dx = 0; dx < s; ++dx) image.at(left + x * s + dx, top + y * s + dy) = c;
        }
    drawTitleBlock(image, head);
    const double y0 = top + side + 10;
    drawScaleBar(image, y0, 2 * d.halfWidthMm, side / (2 * d.halfWidthMm), d.sizeMm);
    // A biaxial stone's fast wave sees an index between alpha and beta, its slow one between beta and gamma
    // (Born & Wolf sec. 15.3); d.nO and d.nE are then beta and gamma.
    const auto index = [](double v) { return formatNumber("%.4f", v); };
    const bool biaxial = d.nA > 0;
    const std::pair<Rgb, std::string> legend[3] = {
        {kOrdinary,
         biaxial ? "pavilion edges seen through the fast wave (n " + index(d.nA) + " to " + index(d.nO) + ")"
                 : "pavilion edges seen through the ordinary wave (n_o " + index(d.nO) + ")"},
        {kExtraordinary,
         biaxial ? "pavilion edges seen through the slow wave (n " + index(d.nO) + " to " + index(d.nE) + ")"
                 : "pavilion edges seen through the extraordinary wave (n_e " + index(d.nE) + ")"},
        {kCrownEdge, "crown facet outlines (purple: both images on one pixel)"}};
    for (int k = 0; k < 3; ++k) {
        const double y = y0 + kScaleBarHeight + 4 + k * kLegendLineStep;
        const Point2 box[4] = {Point2{10, y}, Point2{26, y}, Point2{26, y + 16}, Point2{10, y + 16}};
        fillPolygon(image, box, legend[k].first);
        drawPolyline(image, box, true, 1, kInk);
        drawLegendLine(image, 34, y + 2, legend[k].second);
    }
    return image;
}

}  // namespace facetlight
