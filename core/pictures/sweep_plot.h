#pragma once
// The pictures of a sweep: figures against one varied quantity with their +-1 sigma bands, and a filled
// contour map of a figure over two, with its best point and reference designs marked.
#include <string>
#include <vector>

#include "image/image.h"

namespace facetlight {

// A plot axis: numeric positions `values`, or categories `choices` (plotted at 0, 1, ...).
struct PlotAxis {
    std::string label;  // with its unit, e.g. "pavilion angle (deg)"
    std::vector<double> values;
    std::vector<std::string> choices;

    size_t size() const { return choices.empty() ? values.size() : choices.size(); }
    double position(size_t i) const { return choices.empty() ? values[i] : double(i); }
};

// One figure along the axis: its value and standard error at each position; `valid` false leaves a gap.
struct PlotSeries {
    std::string name;
    std::vector<double> value, sigma;
    std::vector<bool> valid;
};

// Each series as a line with a shaded +-1 sigma band, in its own colour with a legend.
Image seriesPlot(const PlotAxis& x, const std::vector<PlotSeries>& series, const std::string& yLabel,
                 const std::string& title);

struct PlotMarker {
    double x = 0, y = 0;  // in the axes' units (category index for categories)
    std::string label;
    bool best = false;  // drawn as a star; otherwise a ring
};

// The grid's values (x varies slowest: values[i * y.size() + j] at x position i, y position j), bilinear
// between nodes and coloured in bands with a colour scale; invalid nodes grey out the cells they touch.
// Markers outside the axes' ranges are left out.
Image contourMap(const PlotAxis& x, const PlotAxis& y, const PlotSeries& grid, const std::string& valueLabel,
                 const std::vector<PlotMarker>& markers, const std::string& title);

}  // namespace facetlight
