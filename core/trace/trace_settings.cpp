#include "trace/trace_settings.h"

#include <algorithm>
#include <cmath>

#include "optics/material.h"
#include "scene/scene.h"
#include "util/error.h"

namespace facetlight {
namespace {

using namespace settings;

const Schema<FireSettings>& fireSchema() {
    static const Schema<FireSettings> schema({
        boolean(
            "enabled", &FireSettings::enabled,
            {"--fire", "Also trace each photon at the C, D and F lines and measure fire (stats.json: fire)"}),
        number("pupil_mm", &FireSettings::pupilMm, {.lo = 0, .hi = 20, .openLo = true},
               {"--pupil-mm", "Fire: the viewer's pupil diameter", "mm"}),
        number("distance_mm", &FireSettings::distanceMm, {.lo = 10, .hi = 100000},
               {"--viewing-distance-mm", "Fire: the distance from the eye to the stone", "mm"}),
    });
    return schema;
}

// "auto" and the named materials.
std::vector<std::string> materialChoices() {
    std::vector<std::string> names = materialNames();
    names.insert(names.begin(), "auto");
    return names;
}

std::string materialHelp() {
    std::string help = "Material (auto: the design file's own index where it states one, else diamond): ";
    const std::vector<std::string> names = materialChoices();
    for (size_t i = 0; i < names.size(); ++i)
        help += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
    return help;
}

}  // namespace

const Schema<TraceSettings>& traceSettingsSchema() {
    static const Schema<TraceSettings> schema(
        {
            count("photons", &TraceSettings::photons, 1, kMaxPhotons,
                  {"--photons", "Photons to shoot, e.g. 1e6 or 1000000"}),
            count("threads", &TraceSettings::threads, 1, kMaxThreads, {"--threads", "Worker threads"}),
            count("seed", &TraceSettings::seed, 0, UINT64_MAX,
                  {"--seed", "Random seed; the same seed gives the same results"}),
            text("material", inherited<TraceSettings>(&TraceSettings::material),
                 {"--material", materialHelp()}),
            optionalNumber("n", inherited<TraceSettings>(&TraceSettings::constantIndex),
                           {.lo = 1, .hi = 10, .openLo = true},
                           {"--n", "A constant refractive index instead of the material's"}),
            table("custom_material", inherited<TraceSettings>(&TraceSettings::customMaterial),
                  "MaterialDefinition", &readMaterialDefinition, &toJson,
                  {"--custom-material",
                   "A material of your own in place of --material: JSON {\"name\": \"...\", \"n_o\": 1.644, "
                   "\"n_e\": 1.624, \"dispersion\": 0.017, \"density_g_cm3\": 3.06} (or \"n\", or "
                   "\"alpha\", \"beta\", \"gamma\") inline, or a file holding it"}),
            table("absorption", inherited<TraceSettings>(&TraceSettings::absorption), "AbsorptionSpectrum",
                  &readAbsorption, &toJson,
                  {"--absorption",
                   "The material's absorption spectrum: JSON {\"wavelength_nm\": [...], \"ordinary_per_mm\": "
                   "[...], \"extraordinary_per_mm\": [...]} (a biaxial material's rays: \"x_per_mm\", "
                   "\"y_per_mm\", "
                   "\"z_per_mm\"), or the colour 1 mm transmits, "
                   "{\"transmitted_colour\": \"#5b8fd0\"} (or [L*, a*, b*]), or a corundum's chromophores in "
                   "ppma of all atoms, {\"corundum_ppma\": {\"cr\": 100, \"fe_ti\": 20}} (GIA's cross "
                   "sections), inline or in a file"}),
            boolean("dispersion", inherited<TraceSettings>(&TraceSettings::dispersion),
                    {"--no-dispersion", "Trace every photon at 589.3 nm"}),
            count("max_bounces", &TraceSettings::maxBounces, 1, 100000,
                  {"--max-bounces", "Internal reflections before a photon counts as trapped"}),
            choice("polarization", &TraceSettings::polarization, kPolarizationNames,
                   {"--polarization",
                    "on (the default): each photon carries its polarisation (Stokes vector) through every "
                    "facet; "
                    "off: each facet reflects the unpolarised Fresnel average"}),
            choice("intersector", inherited<TraceSettings>(&TraceSettings::intersector), kIntersectorNames,
                   {"--intersector", "Ray-stone intersection"}),
            object("light", inherited<TraceSettings>(&TraceSettings::light), lightSettingsSchema()),
            object("optic_axis", inherited<TraceSettings>(&TraceSettings::opticAxis), opticAxisSchema()),
            number("size_mm", inherited<TraceSettings>(&TraceSettings::sizeMm), {.lo = 0.1, .hi = 1000},
                   {"--size-mm", "The stone's girdle diameter (the width of a fancy shape)", "mm"}),
            object("viewer", inherited<TraceSettings>(&TraceSettings::viewer), viewerSettingsSchema()),
            object("fire", &TraceSettings::fire, fireSchema()),
        },
        // The material's name matters only without an `n` to override it.
        [](const TraceSettings& s, const std::string& path) {
            if (s.customMaterial && (s.constantIndex || s.material != "auto")) {
                const std::string field = fieldPath(path, "custom_material");
                throw Error(field, field + " replaces material and n: give one of them (got " +
                                       (s.constantIndex ? std::string("n") : "material " + s.material) +
                                       " too)");
            }
            if (!s.constantIndex) readChoice(s.material, fieldPath(path, "material"), materialChoices());
            // Concentrations of corundum's chromophores colour corundum only: a named material with its
            // indices (not `n`, a job's own material or "auto", which name no crystal).
            if (s.absorption && s.absorption->corundum) {
                const std::vector<std::string> corundum = corundumMaterialNames();
                if (s.constantIndex || s.customMaterial ||
                    std::find(corundum.begin(), corundum.end(), s.material) == corundum.end()) {
                    std::string names;
                    for (size_t i = 0; i < corundum.size(); ++i)
                        names += (i == 0 ? "" : i + 1 == corundum.size() ? " or " : ", ") + corundum[i];
                    const std::string field = fieldPath(path, "absorption.corundum_ppma");
                    throw Error(field, field + " colours corundum only: choose the material " + names +
                                           " (got " + chosenMaterialName(s) + ")");
                }
            }
            // An extraordinary spectrum needs a uniaxial material ("auto" and `n` are isotropic).
            if (s.absorption && !s.absorption->extraordinaryPerMm.empty() &&
                chosenOptic(s) != Optic::Uniaxial) {
                const std::string field = fieldPath(path, "absorption.extraordinary_per_mm");
                // The spectrum may have come from an extraordinary_transmitted_colour: say both.
                throw Error(field,
                            field + " (or extraordinary_transmitted_colour) needs a uniaxial material (got " +
                                chosenMaterialName(s) + ")");
            }
            // A table of rays along X, Y and Z needs a biaxial material.
            if (s.absorption && s.absorption->trichroic() && chosenOptic(s) != Optic::Biaxial) {
                const std::string field = fieldPath(path, "absorption.x_per_mm");
                throw Error(field, field + " needs a biaxial material (got " + chosenMaterialName(s) + ")");
            }
            if (s.opticAxis.rotationDeg != 0 && chosenOptic(s) != Optic::Biaxial) {
                const std::string field = fieldPath(path, "optic_axis.rotation_deg");
                throw Error(field, field +
                                       " turns a biaxial stone's axes about its gamma axis: it needs a "
                                       "biaxial material (got " +
                                       chosenMaterialName(s) + ")");
            }
            if (s.light.polarizerDeg && s.polarization == PolarizationMode::Off) {
                const std::string field = fieldPath(path, "light.polarizer_deg");
                throw Error(field, field +
                                       " needs polarization on (a polariser means nothing to unpolarised "
                                       "tracing)");
            }
        });
    return schema;
}

TraceSettings TraceSettings::fromJson(const nlohmann::json& j) {
    return traceSettingsSchema().read(j);
}

nlohmann::json toJson(const TraceSettings& s) {
    return traceSettingsSchema().write(s);
}

}  // namespace facetlight
