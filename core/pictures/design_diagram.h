#pragma once
// diagram.png: the stone as a faceting diagram (docs/gemcad.md, "Cutting sheet"): the crown from above, the
// profile from the side and the pavilion from below, every facet outlined and labelled with its tier, beside
// the cutting sheet's tiers (angle and indices) and the stone's size at `sizeMm`.
#include <optional>

#include "image/image.h"
#include "io/cutting_sheet.h"
#include "stone/stone.h"
#include "stone/stone_size.h"

namespace facetlight {

Image designDiagram(const Stone& stone, const std::optional<CuttingSheet>& sheet, const StoneSize& size);

}  // namespace facetlight
