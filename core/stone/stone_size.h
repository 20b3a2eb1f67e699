#pragma once
// A stone at a physical size (docs/gemcad.md, "Size and weight"): the mesh's units scaled so that its girdle
// diameter (the width of a fancy shape) is `sizeMm`, as a job's size_mm says. Weight follows from a density.
#include <optional>

#include "stone/stone.h"

namespace facetlight {

struct StoneSize {
    double lengthMm = 0, widthMm = 0, depthMm = 0;  // girdle outline's long and short extents; table to culet
    double volumeMm3 = 0;
    // The share of the smallest upright block around the stone that the stone keeps (a rough sawn to a block).
    double blockRetention = 0;
    std::optional<double> carats;  // with a density; 1 carat = 0.2 g (the metric carat, CGPM 1907)
};

// Throws Error when the stone has no girdle diameter to scale by or sizeMm is not positive.
StoneSize stoneSize(const Stone& stone, double sizeMm, std::optional<double> densityGcm3);

// The share of a rough's volume the stone keeps (the yield), both read from files in the same units and
// frame (each built with StoneOptions::keepFrame, so that undoing their centring puts them back as drawn).
// Throws Error when the stone does not lie inside a convex rough (a non-convex rough is not checked).
double roughRetention(const Stone& stone, const Stone& rough);

}  // namespace facetlight
