#include "optics/material_definition.h"

#include <algorithm>

#include "settings/settings_schema.h"
#include "util/error.h"

namespace facetlight {
namespace {

using namespace settings;

// Indices as the settings' `n` takes them; a dispersion up to twice rutile's 0.280 (GIA), the most dispersive
// gem; densities up to 25 g/cm^3, above platinum's 21.5.
constexpr NumberRange kIndex{.lo = 1, .hi = 10, .openLo = true};
constexpr double kMaxDispersionBG = 0.56, kMaxDensity = 25;
// Cauchy's n falls by this many times the B-G dispersion from 589.3 to 780 nm, the reddest traced:
// (1/0.5893^2 - 1/0.78^2) / (1/0.4308^2 - 1/0.6867^2) (derived from optics/material.cpp's cauchy()).
constexpr double kRedDropPerBG = 0.3782;
// The least gamma - alpha a biaxial material may have: the crystal interface merges roots closer than about
// 1e-7 of the index (birefringence.cpp), and a material within 1e-7 gave both waves one field and failed its
// trace ('the interface equations are singular'). No gem is within 1e-3 (docs/optics.md's table).
constexpr double kLeastBiaxialSpread = 1e-5;

const Schema<MaterialDefinition>& definitionSchema() {
    static const Schema<MaterialDefinition> schema(
        {
            text("name", &MaterialDefinition::name, {"", "The material's name, for the results"}),
            optionalNumber("n", &MaterialDefinition::n, kIndex, {"", "A singly refracting material's index"}),
            optionalNumber("n_o", &MaterialDefinition::nO, kIndex,
                           {"", "A uniaxial material's ordinary index"}),
            optionalNumber("n_e", &MaterialDefinition::nE, kIndex,
                           {"", "A uniaxial material's extraordinary index"}),
            optionalNumber("alpha", &MaterialDefinition::alpha, kIndex,
                           {"", "A biaxial material's least index"}),
            optionalNumber("beta", &MaterialDefinition::beta, kIndex,
                           {"", "A biaxial material's middle index"}),
            optionalNumber("gamma", &MaterialDefinition::gamma, kIndex,
                           {"", "A biaxial material's greatest index"}),
            number("dispersion", &MaterialDefinition::dispersionBG, {.lo = 0, .hi = kMaxDispersionBG},
                   {"", "n(430.8 nm) - n(686.7 nm), as gem tables give it"}),
            optionalNumber("density_g_cm3", &MaterialDefinition::densityGcm3,
                           {.lo = 0, .hi = kMaxDensity, .openLo = true},
                           {"", "For the stone's weight in carats", "g/cm^3"}),
        },
        [](const MaterialDefinition& d, const std::string& path) {
            const std::string at = path.empty() ? "custom_material" : path;
            if (d.name.empty())
                throw Error(fieldPath(path, "name"), fieldPath(path, "name") + " must not be empty");
            const int forms = int(d.n.has_value()) + int(d.nO || d.nE) + int(d.alpha || d.beta || d.gamma);
            if (forms != 1)
                throw Error(at, at + " must give its indices one way: n (singly refracting), n_o and n_e "
                                     "(uniaxial) or alpha, beta and gamma (biaxial)");
            if ((d.nO || d.nE) && !(d.nO && d.nE)) {
                const std::string missing = fieldPath(path, d.nO ? "n_e" : "n_o");
                throw Error(missing, missing + " is missing: a uniaxial material needs n_o and n_e");
            }
            if (d.nO && *d.nO == *d.nE)
                throw Error(fieldPath(path, "n_e"),
                            fieldPath(path, "n_e") + " equals n_o: give n for a singly refracting material");
            if (d.alpha || d.beta || d.gamma) {
                for (const auto& [key, value] :
                     {std::pair{"alpha", d.alpha}, {"beta", d.beta}, {"gamma", d.gamma}})
                    if (!value)
                        throw Error(fieldPath(path, key), fieldPath(path, key) +
                                                              " is missing: a biaxial material needs alpha, "
                                                              "beta and gamma");
                if (!(*d.alpha < *d.beta && *d.beta < *d.gamma))
                    throw Error(fieldPath(path, "beta"), fieldPath(path, "beta") +
                                                             " must lie strictly between alpha and gamma "
                                                             "(alpha < beta < gamma)");
                if (*d.gamma - *d.alpha < kLeastBiaxialSpread)
                    throw Error(
                        fieldPath(path, "gamma"),
                        fieldPath(path, "gamma") +
                            " must exceed alpha by 1e-5 or more: so nearly singly refracting a material "
                            "cannot be traced as two waves (give n)");
            }
            // Every index must stay above 1 at 780 nm, where the dispersion lowers it most.
            const double least = d.n ? *d.n : d.nO ? std::min(*d.nO, *d.nE) : *d.alpha;
            if (least - kRedDropPerBG * d.dispersionBG <= 1)
                throw Error(
                    fieldPath(path, "dispersion"),
                    fieldPath(path, "dispersion") +
                        " is too large for the indices: the least would fall to 1 or below at 780 nm");
        });
    return schema;
}

}  // namespace

MaterialDefinition readMaterialDefinition(const nlohmann::json& j, const std::string& path) {
    if (!j.is_object())
        throw Error(path, path + " must be an object such as {\"n_o\": 1.644, \"n_e\": 1.624}");
    return definitionSchema().read(j, path);
}

nlohmann::json toJson(const MaterialDefinition& definition) {
    nlohmann::json j = definitionSchema().write(definition);
    // Only the form given: a uniaxial material's JSON has no n, alpha, beta or gamma.
    for (auto it = j.begin(); it != j.end();) it = it.value().is_null() ? j.erase(it) : std::next(it);
    return j;
}

}  // namespace facetlight
