#pragma once
// A material's absorption spectrum (docs/optics.md, "Absorption"): Beer-Lambert coefficients per mm against
// wavelength, for the ordinary wave (an isotropic material's one coefficient) and, for a uniaxial material,
// the extraordinary; for a biaxial one, light vibrating along each principal axis X, Y, Z (trichroism); a job
// gives it as JSON "absorption" (readAbsorption), the CLI as --absorption.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "optics/corundum_chromophores.h"

namespace facetlight {

struct AbsorptionSpectrum {
    std::vector<double> wavelengthNm;        // strictly increasing
    std::vector<double> ordinaryPerMm;       // alpha_o, 1/mm, one per wavelength
    std::vector<double> extraordinaryPerMm;  // alpha_e (uniaxial only); empty: the same as alpha_o
    // A biaxial material's coefficients for light vibrating along its principal axes X, Y and Z (those of
    // its indices alpha, beta and gamma: the rays a dichroscope shows), or all empty. ordinaryPerMm is then
    // their mean, meanOfRays(), what a trace that takes one spectrum uses.
    std::array<std::vector<double>, 3> rayPerMm = {};
    // Where the o and e columns came from a corundum's chromophores (JSON "corundum_ppma"): kept, so that the
    // job's settings say so and the material can be checked to be corundum.
    std::optional<CorundumChromophores> corundum = std::nullopt;

    // Linear between the table's points, constant beyond its ends.
    double ordinary(double wavelengthNm) const;
    double extraordinary(double wavelengthNm) const;
    bool trichroic() const { return !rayPerMm[0].empty(); }
    double ray(int axis, double wavelengthNm) const;  // axis 0, 1, 2: X, Y, Z; trichroic() only
    // ((0 + x / 3) + y / 3) + z / 3 per wavelength: the one way the mean is taken, so that a table read back
    // from JSON equals the shipped one bit for bit.
    static std::vector<double> meanOfRays(const std::array<std::vector<double>, 3>& rays);
    // Whether any coefficient is above 0: a spectrum of zeros traces as no spectrum, bit for bit.
    bool absorbs() const;
    bool operator==(const AbsorptionSpectrum&) const = default;

    static constexpr size_t kMinPoints = 2;     // a line: a flat spectrum is two equal points
    static constexpr size_t kMaxPoints = 2001;  // 200-1000 nm every 0.4 nm
    static constexpr double kMinNm = 100, kMaxNm = 10000;
    static constexpr double kMaxPerMm = 1e6;  // past this no light crosses a micrometre
};

// {"wavelength_nm": [...], "ordinary_per_mm": [...], "extraordinary_per_mm": [...] (optional)}, or
// {"wavelength_nm": [...], "x_per_mm": [...], "y_per_mm": [...], "z_per_mm": [...]} (a biaxial material's
// rays), or a colour by transmission, or {"corundum_ppma": {"cr": ..., "fe_ti": ...}}, checked: throws Error
// naming the field at fault below `path`
// ("absorption.ordinary_per_mm[3]").
AbsorptionSpectrum readAbsorption(const nlohmann::json& j, const std::string& path);
// Where a job's spectrum came from, for a picture's title: its chromophores (describe()) or "the job's
// absorption spectrum" (a table or a colour by transmission).
std::string origin(const AbsorptionSpectrum& spectrum);
nlohmann::json toJson(const AbsorptionSpectrum& spectrum);

// The optical depth left to a photon after a path of `length` through a medium absorbing `alpha` per unit
// length: Beer-Lambert, by the free path drawn at entry (docs/optics.md, "Absorption"); the photon is
// absorbed on the segment where it falls below 0. Written once for float and a packet's lanes.
template <class F>
[[gnu::always_inline]] inline F depthLeft(F depth, F alpha, F length) {
    return depth - alpha * length;
}

// The extraordinary wave's coefficient with its wave normal at theta to the optic axis (cos^2 theta given):
// alpha_o cos^2 theta + alpha_e sin^2 theta, the absorption tensor along the wave's field (docs/optics.md).
inline double extraordinaryAbsorption(double alphaO, double alphaE, double cos2Theta) {
    return alphaO * cos2Theta + alphaE * (1 - cos2Theta);
}

}  // namespace facetlight
