#pragma once
// A material a job defines for itself (docs/optics.md, "A job's own material"): the principal indices at
// 589.3 nm a gemmological table gives, its dispersion and density, for the stones no shipped material is.
// A job gives it as JSON "custom_material" (readMaterialDefinition), the CLI as --custom-material.
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace facetlight {

struct MaterialDefinition {
    std::string name = "custom";
    // One form: `n` (singly refracting); `nO` and `nE` (uniaxial); `alpha` < `beta` < `gamma` (biaxial).
    std::optional<double> n, nO, nE, alpha, beta, gamma;
    double dispersionBG = 0;  // n(430.8 nm) - n(686.7 nm), the same for every principal index; 0: none
    std::optional<double> densityGcm3;
    bool operator==(const MaterialDefinition&) const = default;
};

// {"name": ..., "n": ... | "n_o": ..., "n_e": ... | "alpha": ..., "beta": ..., "gamma": ..., "dispersion":
// ..., "density_g_cm3": ...}, checked: throws Error naming the field at fault below `path`.
MaterialDefinition readMaterialDefinition(const nlohmann::json& j, const std::string& path);
nlohmann::json toJson(const MaterialDefinition& definition);

}  // namespace facetlight
