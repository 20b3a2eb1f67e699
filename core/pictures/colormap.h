#pragma once
// Perceptual colour maps for the plots, and the tick marks of their colour bars.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "image/image.h"

namespace facetlight {

// Matplotlib's viridis (van der Walt & Smith, 2015) for t in [0, 1], as the degree-6 polynomial fit by Matt
// Zucker (shadertoy WlfXRN, CC0); within 0.01 of the table. Dark blue at 0, yellow at 1: readable in grey.
inline Rgb viridis(double t) {
    t = std::clamp(t, 0.0, 1.0);
    static constexpr double c[7][3] = {{0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
                                       {0.1050930431085774, 1.404613529898575, 1.384590162594685},
                                       {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
                                       {-4.634230498983486, -5.799100973351585, -19.33244095627987},
                                       {6.228269936347081, 14.17993336680509, 56.69055260068105},
                                       {4.776384997670288, -13.74514537774601, -65.35303263337234},
                                       {-5.435455855934631, 4.645852612178535, 26.3124352495832}};
    double v[3];
    for (int k = 0; k < 3; ++k) {
        double s = c[6][k];
        for (int i = 5; i >= 0; --i) s = s * t + c[i][k];
        v[k] = std::clamp(s, 0.0, 1.0);
    }
    return {float(v[0]), float(v[1]), float(v[2])};
}

// Text that stays readable on a viridis background.
inline Rgb contrastOn(double t) {
    return t > 0.55 ? Rgb{0, 0, 0} : Rgb{1, 1, 1};
}

// Round tick values 0, step, 2 step, ... up to `max` (about five of them), step 1, 2 or 5 times a power
// of 10.
inline std::vector<double> niceTicks(double max, double& step) {
    if (!(max > 0)) max = 1;
    const double raw = max / 5, mag = std::pow(10.0, std::floor(std::log10(raw)));
    step = raw / mag < 1.5 ? mag : raw / mag < 3.5 ? 2 * mag : raw / mag < 7.5 ? 5 * mag : 10 * mag;
    std::vector<double> ticks;
    for (int i = 0; i * step <= max * (1 + 1e-9); ++i) ticks.push_back(i * step);
    return ticks;
}

// A number with just enough decimals for ticks `step` apart.
inline std::string tickLabel(double v, double step) {
    const int decimals = std::clamp(int(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, v);
    return buffer;
}

// A horizontal colour bar at (x, y) of size w x h for values in [0, max], with ticks and labels below it.
// Values are coloured viridis(pow(v / max, gamma)): a gamma below 1 spreads out the small values.
inline void drawColourBar(Image& image, double x, double y, double w, double h, double max,
                          const std::string& caption, double scale = 2, double gamma = 1) {
    for (int i = 0; i < int(w); ++i) {
        const Rgb c = viridis((i + 0.5) / w);
        for (int j = 0; j < int(h); ++j) image.blend(int(x) + i, int(y) + j, c, 1);
    }
    const Rgb ink{0.1f, 0.1f, 0.1f};
    const Point2 box[4] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
    drawPolyline(image, box, true, 1, ink);
    double step;
    std::vector<double> ticks = niceTicks(max, step);
    if (gamma != 1) ticks = {0, 0.01 * max, 0.05 * max, 0.1 * max, 0.25 * max, 0.5 * max, max};
    for (double t : ticks) {
        const double px = x + w * std::pow(t / max, gamma);
        drawLine(image, {px, y + h}, {px, y + h + 6}, 1.5, ink);
        char label[32];
        std::snprintf(label, sizeof label, "%g", t);
        drawText(image, px, y + h + 9, gamma != 1 ? std::string(label) : tickLabel(t, step), scale, ink,
                 Align::Center);
    }
    drawText(image, x + w / 2, y + h + 12 + textHeight(scale) + 4, caption, scale, ink, Align::Center);
}

}  // namespace facetlight
