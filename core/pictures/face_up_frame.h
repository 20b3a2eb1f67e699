#pragma once
// What the face-up pictures of a stone (the doubling, the colour view) draw alike around the view: a title
// with a two-line summary above it, and a scale bar in mm below it.
#include <string>

#include "image/image.h"

namespace facetlight {

// `title` on the first line, then `summary` split at its first "; " over two lines, each as large as fits the
// picture's width up to `summaryScale` (the title up to 2), `lineStep` pixels apart.
void drawTitleBlock(Image& image, const std::string& title, const std::string& summary, double summaryScale,
                    double lineStep);

// A bar of a round length, about a quarter of the view's `spanMm` (drawn `pixelsPerMm`), at the left edge
// from `y` down, labelled with its length and the stone's size `stoneMm`.
void drawScaleBar(Image& image, double y, double spanMm, double pixelsPerMm, double stoneMm);

}  // namespace facetlight
