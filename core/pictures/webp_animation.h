#pragma once
// An animated WebP (libwebpmux's WebPAnimEncoder) that browsers play in an <img>: lossless, so the ASET
// colours stay exact, looping forever.
#include <span>
#include <string>

#include "image/image.h"

namespace facetlight {

// Frames of one size, each shown for frameMs milliseconds; a frame identical to the one before is merged into
// it (a longer showing), so give frames that must count something that differs, such as a title. Throws Error
// when the encoder fails or the frames differ in size.
std::string encodeAnimatedWebp(std::span<const Image> frames, int frameMs);

}  // namespace facetlight
