#pragma once
// The polariscope's readings as a chart (polariscope.png): the share of the upward light the crossed analyser
// passes against the turntable's angle, and in the subtitle whether and where the stone goes dark.
#include <string>

#include "image/image.h"
#include "viewer/polariscope.h"

namespace facetlight {

Image polariscopeChart(const Polariscope& p, const std::string& title);
// "dark at 0, 90, 180 and 270 deg of a turn: doubly refracting", or that it does not blink.
std::string polariscopeVerdict(const Polariscope& p);

}  // namespace facetlight
