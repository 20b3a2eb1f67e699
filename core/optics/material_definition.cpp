#include "optics/material_definition.h"

#include "settings/settings_schema.h"
#include "util/error.h"

namespace facetlight {
namespace {

using namespace settings;

// Indices as the settings' `n` takes them; a dispersion up to twice rutile's 0.280 (GIA), the most dispersive
// gem; densities up to platinum's 21.5 g/cm^3.
constexpr NumberRange kIndex{.lo = 1, .hi = 10, .openLo = true};

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
            number("dispersion", &MaterialDefinition::dispersionBG, {.lo = 0, .hi = 0.56},
                   {"", "n(430.8 nm) - n(686.7 nm), as gem tables give it"}),
            optionalNumber("density_g_cm3", &MaterialDefinition::densityGcm3,
                           {.lo = 0, .hi = 25, .openLo = true},
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
            }
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
