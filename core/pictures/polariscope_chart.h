#pragma once
// The polariscope's readings as a chart (polariscope.png): the share of the upward light the crossed analyser
// passes against the turntable's angle, and in the subtitle whether and where the stone goes dark.
#include <string>
#include <vector>

#include "image/image.h"
#include "viewer/polariscope.h"

namespace facetlight {

Image polariscopeChart(const Polariscope& p, const std::string& title);
// "dark at 0, 90, 180 and 270 deg of a turn: doubly refracting", or that it does not blink.
std::string polariscopeVerdict(const Polariscope& p);
// The stone seen from above through the analyser at each position (polariscope.webp, one frame a position,
// looping): the light the analyser passes by where it left the stone, smoothed over 5 x 5 cells, on one grey
// scale for all positions (so the blink shows), each frame captioned with its angle and share. Needs the
// readings' pictures (PolariscopeSettings::pictureSize).
std::vector<Image> polariscopeFrames(const Polariscope& p);
constexpr int kPolariscopeFrameMs = 250;  // a frame a position: 36 positions turn half a turn in 9 s

}  // namespace facetlight
