#pragma once
// The inputs of a photon trace (after Tungsten: plain settings structs, kept apart from the algorithm), each
// setting described once in traceSettingsSchema(): JSON, checks, CLI flags and the API schema follow from it.
// A job's settings are flat in JSON: the scene's (material, light, ...) beside the tracer's (photons, ...).
#include <cmath>
#include <cstdint>

#include <nlohmann/json.hpp>

#include "geometry/geometry.h"
#include "scene/scene_settings.h"
#include "settings/settings_schema.h"
#include "util/name_table.h"

namespace facetlight {

// The fire trace (trace/fire_trace.h): each photon also followed at the Fraunhofer C, D and F lines with the
// same random choices, and its red and blue exits compared against what the viewer's pupil spans.
struct FireSettings {
    bool enabled = false;
    double pupilMm = 4;       // pupil diameter
    double distanceMm = 250;  // from the eye to the stone
    // The angle the pupil spans seen from the stone: 2 atan(pupil / 2 / distance), 0.917 deg by default.
    double pupilAngleDeg() const { return degrees(2 * std::atan(pupilMm / 2 / distanceMm)); }
};

// How light's polarisation is traced (docs/optics.md, "Polarisation"): on (the default, since it moves the
// shipped brilliants' figures by more than 2 standard errors at 1e6 photons: docs/physics.md), each photon
// carries its Stokes vector through every facet; off, every facet reflects the unpolarised Fresnel average
// (the photon forgets what earlier facets did to it), the tracer as it was before.
enum class PolarizationMode { Off, On };
inline constexpr NameTable<PolarizationMode, 2> kPolarizationNames{
    {{{PolarizationMode::Off, "off"}, {PolarizationMode::On, "on"}}}};

// The world's settings (the scene's) and the tracer's own.
struct TraceSettings : SceneSettings {
    uint64_t photons = 1'000'000;
    int threads = 1;
    uint64_t seed = 1;     // photon i draws from Rng(seed, i)
    int maxBounces = 512;  // internal reflections after which a photon counts as trapped (docs/optics.md)
    PolarizationMode polarization = PolarizationMode::On;
    FireSettings fire;

    // Missing keys keep their defaults; throws Error naming the field by its dotted path.
    static TraceSettings fromJson(const nlohmann::json& j);
};

constexpr uint64_t kMaxPhotons = 10'000'000'000ULL;
constexpr int kMaxThreads = 1024;

const settings::Schema<TraceSettings>& traceSettingsSchema();
nlohmann::json toJson(const TraceSettings& s);

}  // namespace facetlight
