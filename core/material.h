#pragma once
// Refractive index as a function of wavelength (Sellmeier), for the materials in docs/optics.md, or a
// constant index for an `n` override.
#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace facetlight {

class Material {
  public:
    // One of materialNames(); throws Error listing the known names otherwise.
    static Material byName(std::string_view name);
    // A dispersionless material of index n (1 < n <= 10).
    static Material constant(double n);

    const std::string& name() const { return name_; }
    // Refractive index at a vacuum wavelength in nanometres.
    double index(double wavelengthNm) const;
    // n at the sodium D line (589.3 nm) and the gemmological dispersion n(430.8 nm) - n(686.7 nm).
    double indexD() const { return index(kSodiumD); }
    double dispersionBG() const { return index(430.8) - index(686.7); }
    bool dispersive() const { return terms_ > 0; }

    static constexpr double kSodiumD = 589.3;

  private:
    std::string name_;
    int terms_ = 0;  // Sellmeier terms; 0 means the constant index n0_
    std::array<double, 3> b_{}, c2_{};
    double n0_ = 1;
};

std::vector<std::string> materialNames();

}  // namespace facetlight
