#pragma once
// Refractive index as a function of wavelength, for the materials in docs/optics.md ("Materials"), or a
// constant index for an `n` override. A doubly refracting material has three principal indices, each with its
// own dispersion: n_o, n_o, n_e for a uniaxial crystal, alpha, beta, gamma for a biaxial one.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "optics/absorption.h"
#include "optics/material_definition.h"

namespace facetlight {

// The optic class: one index (cubic crystals, glasses), one optic axis (n_o, n_e) or two (alpha, beta, gamma).
enum class Optic { Isotropic, Uniaxial, Biaxial };

// One principal index against wavelength L (micrometres), in one of the published forms (docs/optics.md):
// Sellmeier n^2 = A + sum B_i L^2 / (L^2 - C_i) + D L^2 (or B_i / (L^2 - C_i) where `poleOnly`), with C_i
// the squared resonance wavelengths; Cauchy n = A + B_0 / L^2; or the constant A.
struct Dispersion {
    enum class Form { Constant, Sellmeier, Cauchy };
    Form form = Form::Constant;
    double a = 1;
    std::array<double, 3> b{}, c2{};
    int terms = 0;
    bool poleOnly = false;  // terms B / (L^2 - C) rather than B L^2 / (L^2 - C)
    double d = 0;           // the infrared term's D L^2
    bool operator==(const Dispersion&) const = default;

    template <class D>
    [[gnu::always_inline]] D at(D wavelengthNm) const;
};

class Material {
  public:
    // One of materialNames(); throws Error listing the known names otherwise.
    static Material byName(std::string_view name);
    // A dispersionless material of index n (1 < n <= 10), named `name`.
    static Material constant(double n, std::string name = "custom");
    // A job's own material: Cauchy through its indices and dispersion, as for the shipped materials no fit is
    // published for (docs/optics.md, "A job's own material"); `definition` must have passed its reader.
    static Material defined(const MaterialDefinition& definition);

    const std::string& name() const { return name_; }
    // The index single-index code traces: n_o for a uniaxial crystal (the ordinary ray sees it in every
    // direction), beta for a biaxial one (between alpha and gamma; the index along an optic axis).
    double index(double wavelengthNm) const { return indexOf(wavelengthNm); }
    // n at the sodium D line (589.3 nm) and the gemmological dispersion n(430.8 nm) - n(686.7 nm), of index().
    double indexD() const { return index(kSodiumD); }
    double dispersionBG() const { return index(430.8) - index(686.7); }
    bool dispersive() const { return axes_[1].form != Dispersion::Form::Constant; }
    // g/cm^3, for weights; none for a constant index (an `n` or a design file's index names no material).
    std::optional<double> densityGcm3() const { return density_ > 0 ? std::optional(density_) : std::nullopt; }

    // Beer-Lambert absorption (docs/optics.md, "Absorption"): none (clear), a coloured material's published
    // spectrum (optics/gem_spectra.h), or a spectrum a job gives in its place.
    const std::optional<AbsorptionSpectrum>& absorption() const { return absorption_; }
    Material withAbsorption(std::optional<AbsorptionSpectrum> spectrum) const {
        Material m = *this;
        m.absorption_ = std::move(spectrum);
        return m;
    }

    Optic optic() const { return optic_; }
    // n_o, n_o, n_e (uniaxial); alpha, beta, gamma (biaxial, alpha < beta < gamma); n, n, n (isotropic).
    std::array<double, 3> principalIndices(double wavelengthNm) const;
    // principalIndices()[axis] alone (a birefringent trace's per-photon index: one dispersion formula, not
    // three).
    double principalIndex(int axis, double wavelengthNm) const {
        return principalIndexOf(axis, wavelengthNm);
    }
    // At 589.3 nm, as gemmologists quote them: the largest less the smallest principal index (0 for
    // isotropic), and the optic sign: +1 when n_e > n_o, or for biaxial when gamma is the acute bisectrix
    // (twoVzDegrees() < 90); -1 otherwise; 0 for isotropic and for a biaxial crystal at 2V = 90 deg exactly.
    double birefringence() const;
    int opticSign() const;
    // The angle between a biaxial crystal's optic axes about gamma at 589.3 nm, in degrees (0 to 180; the
    // acute 2V is min(2Vz, 180 - 2Vz)), from the principal indices: cos^2 Vz = alpha^2 (gamma^2 - beta^2) /
    // (beta^2 (gamma^2 - alpha^2)). 0 for uniaxial and isotropic.
    double twoVzDegrees() const;

    static constexpr double kSodiumD = 589.3;
    // index() for any number type with the operators of double (lanes of a packet): the same bits per lane.
    // Always inlined, so that lanes are computed with their SIMD target's instructions.
    template <class D>
    [[gnu::always_inline]] D indexOf(D wavelengthNm) const {
        return axes_[1].at(wavelengthNm);
    }
    // principalIndex() likewise.
    template <class D>
    [[gnu::always_inline]] D principalIndexOf(int axis, D wavelengthNm) const {
        return axes_[size_t(axis)].at(wavelengthNm);
    }

  private:
    std::string name_;
    Optic optic_ = Optic::Isotropic;
    // Principal indices in the order of principalIndices(); axes_[1] is index()'s.
    std::array<Dispersion, 3> axes_{};
    double density_ = 0;
    std::optional<AbsorptionSpectrum> absorption_;
};

std::vector<std::string> materialNames();
// The named materials that are corundum (Malitson & Dodge's indices): sapphire, ruby, blue_sapphire; what a
// job's corundum_ppma may colour (optics/corundum_chromophores.h).
std::vector<std::string> corundumMaterialNames();
// "isotropic", "uniaxial" or "biaxial" (stats.json's material.optic).
const char* opticName(Optic optic);

template <class D>
inline D Dispersion::at(D wavelengthNm) const {
    if (form == Form::Constant) return D(a);
    using std::sqrt;
    const D l = wavelengthNm * D(1e-3), l2 = l * l;
    if (form == Form::Cauchy) return D(a) + D(b[0]) / l2;
    D n2(a);
    if (poleOnly)
        for (int i = 0; i < terms; ++i) n2 = n2 + D(b[i]) / (l2 - D(c2[i]));
    else
        for (int i = 0; i < terms; ++i) n2 = n2 + D(b[i]) * l2 / (l2 - D(c2[i]));
    if (d != 0) n2 = n2 + D(d) * l2;
    return sqrt(n2);
}

}  // namespace facetlight
