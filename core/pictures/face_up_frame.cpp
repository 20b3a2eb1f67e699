#include "pictures/face_up_frame.h"

#include <algorithm>

#include "util/number_text.h"

namespace facetlight {
namespace {

const Rgb kInk{0.1f, 0.1f, 0.1f};

}  // namespace

void drawTitleBlock(Image& image, const std::string& title, const std::string& summary, double summaryScale,
                    double lineStep) {
    const size_t cut = summary.find("; ");
    const std::string lines[3] = {title, summary.substr(0, cut),
                                  cut == std::string::npos ? "" : summary.substr(cut + 2)};
    const double width = image.width();
    for (int k = 0; k < 3; ++k) {
        const double scale =
            std::min(k == 0 ? 2.0 : summaryScale, (width - 10) / std::max(1.0, textWidth(lines[k], 1)));
        drawText(image, width / 2.0, k == 0 ? 6 : 14 + lineStep * k, lines[k], scale, kInk, Align::Center);
    }
}

void drawScaleBar(Image& image, double y, double spanMm, double pixelsPerMm, double stoneMm) {
    double bar = 0.1;
    for (double b : {0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0})
        if (b <= 0.3 * spanMm) bar = b;
    const double end = 10 + bar * pixelsPerMm;
    drawLine(image, {10, y + 8}, {end, y + 8}, 3, kInk);
    drawLine(image, {10, y + 2}, {10, y + 14}, 1.5, kInk);
    drawLine(image, {end, y + 2}, {end, y + 14}, 1.5, kInk);
    drawText(image, end + 8, y + 1,
             formatNumber("%g", bar) + " mm (stone " + formatNumber("%g", stoneMm) + " mm across)", 2, kInk);
}

}  // namespace facetlight
