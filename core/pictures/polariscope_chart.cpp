#include "pictures/polariscope_chart.h"

#include <vector>

#include "pictures/share_chart.h"
#include "util/number_text.h"

namespace facetlight {

std::string polariscopeVerdict(const Polariscope& p) {
    if (!p.blinks) return "no blink as it turns: singly refracting, or seen along an optic axis";
    std::string angles;
    for (size_t k = 0; k < p.darkAnglesDeg.size(); ++k)
        angles += (k == 0 ? "" : k + 1 == p.darkAnglesDeg.size() ? " and " : ", ") +
                  formatNumber("%g", p.darkAnglesDeg[k]);
    return "dark at " + angles + " deg of a turn: doubly refracting";
}

Image polariscopeChart(const Polariscope& p, const std::string& title) {
    std::vector<SharePoint> points;
    for (const PolariscopeReading& r : p.readings) points.push_back({r.angleDeg, r.share(), r.shareStderr()});
    return shareChart(points, {title, polariscopeVerdict(p), "stone turned, lit from below (deg)",
                               "through crossed polarisers (% of the upward light)"});
}

}  // namespace facetlight
