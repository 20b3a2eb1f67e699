#pragma once
// Refractive index as a function of wavelength (Sellmeier), for the materials in docs/optics.md, or a
// constant index for an `n` override.
#include <array>
#include <cmath>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facetlight {

class Material {
  public:
    // One of materialNames(); throws Error listing the known names otherwise.
    static Material byName(std::string_view name);
    // A dispersionless material of index n (1 < n <= 10), named `name`.
    static Material constant(double n, std::string name = "custom");

    const std::string& name() const { return name_; }
    // Refractive index at a vacuum wavelength in nanometres.
    double index(double wavelengthNm) const { return sellmeier(wavelengthNm); }
    // n at the sodium D line (589.3 nm) and the gemmological dispersion n(430.8 nm) - n(686.7 nm).
    double indexD() const { return index(kSodiumD); }
    double dispersionBG() const { return index(430.8) - index(686.7); }
    bool dispersive() const { return terms_ > 0; }
    // g/cm^3, for weights; none for a constant index (an `n` or a design file's index names no material).
    std::optional<double> densityGcm3() const { return density_ > 0 ? std::optional(density_) : std::nullopt; }

    static constexpr double kSodiumD = 589.3;
    // index() for any number type with the operators of double (lanes of a packet): the same bits per lane.
    // Always inlined, so that lanes are computed with their SIMD target's instructions.
    template <class D>
    [[gnu::always_inline]] D indexOf(D wavelengthNm) const {
        return sellmeier(wavelengthNm);
    }

  private:
    template <class D>
    [[gnu::always_inline]] D sellmeier(D wavelengthNm) const;

    std::string name_;
    int terms_ = 0;  // Sellmeier terms; 0 means the constant index n0_
    std::array<double, 3> b_{}, c2_{};
    double n0_ = 1;
    double density_ = 0;
};

std::vector<std::string> materialNames();

// n^2 - 1 = sum B L^2 / (L^2 - C^2), L in micrometres (docs/optics.md).
template <class D>
inline D Material::sellmeier(D wavelengthNm) const {
    if (terms_ == 0) return D(n0_);
    using std::sqrt;
    const D l = wavelengthNm * D(1e-3), l2 = l * l;
    D n2(1.0);
    for (int i = 0; i < terms_; ++i) n2 = n2 + D(b_[i]) * l2 / (l2 - D(c2_[i]));
    return sqrt(n2);
}

}  // namespace facetlight
