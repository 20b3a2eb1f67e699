#pragma once
// What the face-up pictures of a stone (the doubling, the colour view) draw alike around the view: a title
// with its summary above it, a scale bar in mm and legend lines below it, all at the legible size (scale 2,
// glyphs 14 pixels high) where they fit.
#include <string>
#include <vector>

#include "image/image.h"

namespace facetlight {

// The lines above the view: the title, then the summary, each wrapped to the picture's width.
struct TitleBlock {
    std::vector<std::string> title, summary;
    int height() const;  // pixels, from the picture's top to below the last line
};
TitleBlock titleBlock(const std::string& title, const std::string& summary, int pictureWidth);
void drawTitleBlock(Image& image, const TitleBlock& block);

// Pixels from one legend line to the next.
inline constexpr int kLegendLineStep = 20;
// `text` from (x, y) on one line, at the legible size or as large as fits the picture's width.
void drawLegendLine(Image& image, double x, double y, const std::string& text);

// A bar of a round length, about a quarter of the view's `spanMm` (drawn `pixelsPerMm`), at the left edge
// from `y` down, labelled with its length and the stone's size `stoneMm`; kScaleBarHeight pixels high.
inline constexpr int kScaleBarHeight = 20;
void drawScaleBar(Image& image, double y, double spanMm, double pixelsPerMm, double stoneMm);

}  // namespace facetlight
