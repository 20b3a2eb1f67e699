#include "pictures/polariscope_chart.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "pictures/share_chart.h"
#include "util/number_text.h"

namespace facetlight {

std::string polariscopeVerdict(const Polariscope& p) {
    if (p.reaction == PolariscopeReaction::StaysDark)
        return "stays dark as it turns: singly refracting, or seen along an optic axis";
    if (p.reaction == PolariscopeReaction::StaysLight)
        return "stays light as it turns: the facets' reflections hide single or double refraction";
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

std::vector<Image> polariscopeFrames(const Polariscope& p) {
    std::vector<Image> frames;
    if (p.readings.empty() || p.readings.front().seen.empty()) return frames;
    const int n = int(std::lround(std::sqrt(double(p.readings.front().seen.size()))));
    // Each cell the sum over its 5 x 5 neighbourhood: a few photons a cell are too few to see by.
    std::vector<std::vector<double>> smooth;
    double brightest = 1;
    for (const PolariscopeReading& r : p.readings) {
        std::vector<double> s(r.seen.size(), 0);
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                double sum = 0;
                for (int dy = -2; dy <= 2; ++dy)
                    for (int dx = -2; dx <= 2; ++dx)
                        if (x + dx >= 0 && x + dx < n && y + dy >= 0 && y + dy < n)
                            sum += r.seen[size_t(y + dy) * size_t(n) + size_t(x + dx)];
                s[size_t(y) * size_t(n) + size_t(x)] = sum;
                brightest = std::max(brightest, sum);
            }
        smooth.push_back(std::move(s));
    }
    const Rgb ink{0.85f, 0.85f, 0.85f};
    // A small grid's cells drawn as blocks, so that the frame holds its label: at least 160 pixels across.
    const int cell = std::max(1, 160 / n), side = n * cell;
    for (size_t k = 0; k < p.readings.size(); ++k) {
        Image image(side, side + 24, {0, 0, 0});
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x) {
                // Square root: the dim extinction positions stay visibly dark against a bright blink.
                const size_t at = size_t(y / cell) * size_t(n) + size_t(x / cell);
                const float v = float(std::sqrt(smooth[k][at] / brightest));
                image.at(x, y + 24) = {v, v, v};
            }
        const PolariscopeReading& r = p.readings[k];
        drawText(image, 4, 4,
                 formatNumber("%g", r.angleDeg) + " deg: " + formatNumber("%.0f", 100 * r.share()) + " %",
                 1.5, ink);
        frames.push_back(std::move(image));
    }
    return frames;
}

}  // namespace facetlight
