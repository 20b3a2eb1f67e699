#include "pictures/face_up_frame.h"

#include <algorithm>

#include "util/number_text.h"

namespace facetlight {
namespace {

const Rgb kInk{0.1f, 0.1f, 0.1f};

constexpr double kLegible = 2, kTitleScale = 2.4, kTop = 6;

double fittingScale(const std::string& text, double width, double largest) {
    return std::min(largest, width / std::max(1.0, textWidth(text, 1)));
}

double lineStep(double scale) {
    return textHeight(scale) + 4;
}

}  // namespace

int TitleBlock::height() const {
    return int(kTop + lineStep(kTitleScale) * double(title.size()) + 4 +
               lineStep(kLegible) * double(summary.size()) + 6);
}

TitleBlock titleBlock(const std::string& title, const std::string& summary, int pictureWidth) {
    // The title broken only between its parts, each shrunk to fit if it must: no word left alone on a line.
    return {wrapToFit(title, kTitleScale, pictureWidth - 10, false),
            wrapToFit(summary, kLegible, pictureWidth - 10)};
}

void drawTitleBlock(Image& image, const TitleBlock& block) {
    const double width = image.width();
    double y = kTop;
    for (const std::string& line : block.title) {
        drawText(image, width / 2, y, line, fittingScale(line, width - 10, kTitleScale), kInk, Align::Center);
        y += lineStep(kTitleScale);
    }
    y += 4;
    for (const std::string& line : block.summary) {
        drawText(image, width / 2, y, line, fittingScale(line, width - 10, kLegible), kInk, Align::Center);
        y += lineStep(kLegible);
    }
}

void drawLegendLine(Image& image, double x, double y, const std::string& text) {
    drawText(image, x, y, text, fittingScale(text, image.width() - 5 - x, kLegible), kInk);
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
