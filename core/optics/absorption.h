#pragma once
// A material's absorption spectrum (docs/optics.md, "Absorption"): Beer-Lambert coefficients per mm against
// wavelength, for the ordinary wave (an isotropic material's one coefficient) and, for a uniaxial material,
// the extraordinary; a job gives it as JSON "absorption" (readAbsorption), the CLI as --absorption.
#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace facetlight {

struct AbsorptionSpectrum {
    std::vector<double> wavelengthNm;        // strictly increasing
    std::vector<double> ordinaryPerMm;       // alpha_o, 1/mm, one per wavelength
    std::vector<double> extraordinaryPerMm;  // alpha_e (uniaxial only); empty: the same as alpha_o

    // Linear between the table's points, constant beyond its ends.
    double ordinary(double wavelengthNm) const;
    double extraordinary(double wavelengthNm) const;
    // Whether any coefficient is above 0: a spectrum of zeros traces as no spectrum, bit for bit.
    bool absorbs() const;
    bool operator==(const AbsorptionSpectrum&) const = default;

    static constexpr size_t kMinPoints = 2;     // a line: a flat spectrum is two equal points
    static constexpr size_t kMaxPoints = 2001;  // 200-1000 nm every 0.4 nm
    static constexpr double kMinNm = 100, kMaxNm = 10000;
    static constexpr double kMaxPerMm = 1e6;  // past this no light crosses a micrometre
};

// {"wavelength_nm": [...], "ordinary_per_mm": [...], "extraordinary_per_mm": [...] (optional)}, checked:
// throws Error naming the field at fault below `path` ("absorption.ordinary_per_mm[3]").
AbsorptionSpectrum readAbsorption(const nlohmann::json& j, const std::string& path);
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
