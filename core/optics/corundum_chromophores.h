#pragma once
// Corundum coloured by its chromophores (docs/optics.md, "Corundum by its chromophores"): GIA's absorption
// cross sections of Cr3+ and of the Fe2+-Ti4+ pair (Dubinsky, Stone-Sundberg & Emmett, Gems & Gemology 56(1),
// 2020), times the concentrations a job gives, make the stone's ordinary and extraordinary spectra.
#include <string>
#include <vector>

namespace facetlight {

// Concentrations in ppma: parts per million of all atoms (Al, O and the dopants). fe_ti counts Fe2+-Ti4+
// pairs, as GIA's cross section is per pair.
struct CorundumChromophores {
    double crPpma = 0;
    double feTiPpma = 0;
    bool operator==(const CorundumChromophores&) const = default;

    // 1 % of the atoms (1 wt% Cr2O3 is about 2700 ppma, derived); past it GIA's samples give no cross
    // section.
    static constexpr double kMaxPpma = 10000;
};

// Atoms per cm^3 of corundum: 5 per Al2O3, density 4.00 g/cm^3 (GIA Gem Reference Guide, as
// docs/optics.md's materials table), molar mass 101.96 g/mol, Avogadro's 6.02214076e23 (SI, exact).
inline constexpr double kCorundumAtomsPerCm3 = 5 * 6.02214076e23 * 4.00 / 101.96;

// "Cr3+ 1000 ppma, Fe2+-Ti4+ 20 ppma" (the chromophores present): what a picture's title names the colour by.
std::string describe(const CorundumChromophores& c);

enum class CorundumRay { Ordinary, Extraordinary };  // E perp c, E || c

// The cross sections' wavelengths (380-780 nm every 2 nm) and sigma in cm^2 per ion (Cr3+) or per pair
// (Fe2+-Ti4+) at each, for one ray.
const std::vector<double>& corundumWavelengthsNm();
std::vector<double> chromiumCrossSectionCm2(CorundumRay ray);
std::vector<double> ironTitaniumCrossSectionCm2(CorundumRay ray);

// alpha per mm of one ray at corundumWavelengthsNm(): sum over chromophores of sigma N, N = ppma 1e-6
// kCorundumAtomsPerCm3, natural-log (I = I0 exp(-alpha L)), cm^-1 to mm^-1.
std::vector<double> corundumAbsorptionPerMm(const CorundumChromophores& c, CorundumRay ray);

}  // namespace facetlight
