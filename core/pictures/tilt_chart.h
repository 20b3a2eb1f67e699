#pragma once
// Light return against tilt (like GemRay's brightness-versus-tilt curve): each frame of a tilt series as a
// point with its +-1 standard error bar, tilt in degrees across, the lit share of the face-up area in percent
// up, and the series' scintillation in the subtitle.
#include <string>

#include "image/image.h"
#include "render/tilt_series.h"

namespace facetlight {

Image tiltChart(const TiltSeries& series, const std::string& title);
// Its subtitle: the scintillation with its standard error to the error's own digits ("7.41 +- 0.04 % per
// frame"), never an error rounded to 0.
std::string tiltChartSubtitle(const TiltSeries& series);

}  // namespace facetlight
