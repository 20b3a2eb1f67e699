#pragma once
// A share against an angle, each point with its +-1 standard error bar: the angle in degrees across, the share
// in percent up on whole 5 % steps around the data, a title and a subtitle. The tilt series' chart (light
// return against tilt) and the polariscope's (the analyser's share against the turntable) are drawn with it.
#include <string>
#include <vector>

#include "image/image.h"

namespace facetlight {

struct SharePoint {
    double angleDeg;
    double share, standardError;  // 0..1
};

struct ShareChartLabels {
    std::string title, subtitle;
    std::string across;  // the angle's name, with its unit
    std::string up;      // the share's, with its unit
};

Image shareChart(const std::vector<SharePoint>& points, const ShareChartLabels& labels);

}  // namespace facetlight
