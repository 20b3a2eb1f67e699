#pragma once
// The polar plot of where the light leaving the crown goes (the tally: stats/angular_histogram.h).
#include <string>

#include "image/image.h"
#include "stats/angular_histogram.h"

namespace facetlight {

// A polar plot: angle from the vertical as the radius (0 at the centre, 90 degrees at the rim), azimuth
// around (0 to the right, 90 up), each bin coloured by its photons per steradian relative to the busiest bin,
// with labelled rings at 30, 60 and 90 degrees, azimuth spokes and a colour bar. `subtitle` says what was
// counted.
Image angularPlot(const AngularHistogram& histogram, const std::string& subtitle);

}  // namespace facetlight
