#pragma once
// colour.png: the stone face-up in true colour (viewer/colour_view.h) with its title, a scale bar in mm and a
// legend of the illuminant, the stone's size and its colour figures.
#include <string>

#include "image/image.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "viewer/colour_view.h"

namespace facetlight {

std::string colourTitle(const Stone& stone, const TraceSettings& settings);
// "L* 62.1 +- 0.3 (spread 14.2), a* ...; windowed 3.1 %": the figures in one line (the picture wraps it).
std::string colourSummary(const ColourView& view);
Image colourPicture(const ColourView& view, const std::string& title);

}  // namespace facetlight
