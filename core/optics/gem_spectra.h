#pragma once
// The absorption spectra the coloured materials ship with (docs/optics.md, "Coloured materials"): measured
// absorbance of a named sample at its thickness, as published, turned into coefficients per mm.
#include <optional>
#include <string_view>

#include "optics/absorption.h"

namespace facetlight {

// The spectrum of material `name`, or none for a clear material. Each published column of decadic absorbance
// A at thickness d becomes alpha = ln(10) (A - A_min) / d per mm, A_min the column's smallest value (the
// files keep the two faces' reflection and the instrument's offset, which the tracer must not count twice).
std::optional<AbsorptionSpectrum> gemSpectrum(std::string_view name);

}  // namespace facetlight
