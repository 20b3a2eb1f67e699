#pragma once
// The ASET picture: the view of render/aset.h, each pixel the mix of its rays' class colours (AGS's: blue
// head, red bright, green low, black or white leakage), with a title and a legend giving each class's angles
// and share of the face-up area.
#include "image/image.h"
#include "render/aset.h"

namespace facetlight {

Rgb asetColour(AsetClass c, const AsetSettings& settings);
Image asetPicture(const AsetView& view, const AsetSettings& settings, const std::string& title);

}  // namespace facetlight
