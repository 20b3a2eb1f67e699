#pragma once
// A sweep's pictures: its figures against one varied quantity, or a figure's map over two with the best point
// and the shipped reference designs (GIA reference, Tolkowsky) marked.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "image/image.h"
#include "sweep/sweep_run.h"

namespace facetlight {

// The traced point with the highest `figure`; none when no point could be traced.
std::optional<size_t> highestPoint(const SweepResult& result, const std::string& figure);

// The curves' title: the design with the parameters held at other than their defaults, the light, the
// photons and the highest point of the first figure ("round_brilliant with crown 34.5; ...; highest
// brightness 0.4110 +- 0.0021 at pavilion 41.75").
std::string sweepCurvesTitle(const SweepResult& result, const std::vector<std::string>& figures);

// Every figure in `figures` against the one axis with more than one value, with +-1 sigma bands.
Image sweepCurves(const SweepResult& result, const std::vector<std::string>& figures);
// `figure` as a filled contour map over the two axes.
Image sweepMap(const SweepResult& result, const std::string& figure);

// The pictures the sweep's shape calls for, by file name: "curves.png" when one axis varies, else
// "map_<figure>.png" for each figure. Throws Error for an unknown figure.
std::vector<std::pair<std::string, Image>> sweepPictures(const SweepResult& result,
                                                         const std::vector<std::string>& figures);

}  // namespace facetlight
