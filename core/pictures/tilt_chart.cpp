#include "pictures/tilt_chart.h"

#include <vector>

#include "pictures/share_chart.h"
#include "util/number_text.h"

namespace facetlight {

std::string tiltChartSubtitle(const TiltSeries& series) {
    // stb_easy_font has no plus-minus sign. An error of 0 (no pixel switched, or every one) is no error to
    // print: the share alone.
    const AsetShare s = series.scintillation();
    const std::string share = s.standardError > 0 ? formatWithError(100 * s.share, 100 * s.standardError)
                                                  : formatNumber("%.1f", 100 * s.share);
    return "ASET view, lit = bright or low light; scintillation " + share + " % per frame";
}

Image tiltChart(const TiltSeries& series, const std::string& title) {
    std::vector<SharePoint> points;
    for (const TiltFrame& f : series.frames)
        points.push_back({f.tiltDeg, f.lightReturn.share, f.lightReturn.standardError});
    return shareChart(points, {title, tiltChartSubtitle(series), "tilt about " + tiltAxisName(series.axisDeg) + " (deg)",
                               "light return (% of face-up area)"});
}

}  // namespace facetlight
