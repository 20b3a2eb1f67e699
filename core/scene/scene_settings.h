#pragma once
// The world a job happens in (after Tungsten: plain settings, apart from the algorithms): the stone's
// material, the light, and how rays meet the stone. The tracer's own settings extend these
// (trace/trace_settings.h), where every field is described once.
#include <optional>
#include <string>

#include "optics/absorption.h"
#include "optics/light_settings.h"
#include "optics/material_definition.h"
#include "optics/optic_axis.h"
#include "optics/viewer_settings.h"
#include "util/name_table.h"

namespace facetlight {

enum class IntersectorKind { Auto, Convex, Embree };
inline constexpr NameTable<IntersectorKind, 3> kIntersectorNames{{{{IntersectorKind::Auto, "auto"},
                                                                   {IntersectorKind::Convex, "convex"},
                                                                   {IntersectorKind::Embree, "embree"}}}};

struct SceneSettings {
    // A name of materialNames(), or "auto": the design file's own index (GemCad "I") where it states one, else
    // diamond.
    std::string material = "auto";
    std::optional<double> constantIndex;  // a constant refractive index overriding the material's (JSON "n")
    // A job's own material (JSON "custom_material"), in place of `material` and `n`.
    std::optional<MaterialDefinition> customMaterial;
    // The material's absorption (JSON "absorption"): none, or a user's spectrum (docs/optics.md,
    // "Absorption").
    std::optional<AbsorptionSpectrum> absorption;
    bool dispersion = true;               // refraction by wavelength in 380-780 nm; false: all at 589.3 nm
    IntersectorKind intersector = IntersectorKind::Auto;
    LightSettings light;
    OpticAxisSettings opticAxis;  // a uniaxial material's, traced with polarisation on
    // The stone's size: its girdle diameter (the width of a fancy shape), which the mesh's units are scaled
    // to. A round brilliant of 1 carat is about 6.5 mm across (docs/physics.md, "Viewer figures").
    // Absorption's path lengths are in mm at this size; every figure without absorption is scale-free.
    double sizeMm = 6.5;
    // How a person looks at it: the viewer, the office and spot set-ups, the motion (the viewer figures).
    ViewerSettings viewer;
};

}  // namespace facetlight
