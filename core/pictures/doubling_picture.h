#pragma once
// The doubling seen face-up (doubling.png): the stone in grey with the pavilion's edges as the ordinary wave
// shows them in blue and as the extraordinary wave shows them in orange, the crown's facet outlines, a scale
// bar in mm, a title naming the stone, material and optic axis, the measured doubling and a legend.
#include <string>

#include "image/image.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "viewer/doubling.h"

namespace facetlight {

Image doublingPicture(const Doubling& d, const std::string& title);
// "Doubling: round_brilliant, zircon, optic axis 45 deg from the table's normal toward 0 deg".
std::string doublingTitle(const Stone& stone, const TraceSettings& settings);
// What was measured: "through the table: median 0.088 mm (quartiles 0.081-0.097), 1.35 % of the girdle,
// 12.1 arcmin through a 10x loupe; through the whole crown: ...", or that the stone shows one image and why.
std::string doublingSummary(const Doubling& d);

}  // namespace facetlight
