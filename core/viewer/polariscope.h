#pragma once
// The polariscope, a gemmologist's first test of an unknown stone (docs/optics.md, "The polariscope"): the
// stone on a turntable between crossed polarisers, lit from below. A singly refracting stone stays dark as it
// turns; a doubly refracting one blinks, dark four times a turn, where the lower polariser lies along the
// field of one of its two waves; a faceted stone may stay light whichever it is, its reflections turning the
// polarisation.
#include <cstdint>
#include <vector>

#include <nlohmann/json.hpp>

#include "settings/settings_schema.h"
#include "stone/stone.h"
#include "trace/trace_settings.h"
#include "util/name_table.h"
#include "util/run_control.h"

namespace facetlight {

// The light below the lower polariser: a parallel beam straight up, or a diffusing light box (a Lambertian
// emitter: the same radiance from every direction of the lower hemisphere), as most polariscopes have.
enum class PolariscopeLamp { Collimated, Diffuse };
inline constexpr NameTable<PolariscopeLamp, 2> kPolariscopeLampNames{
    {{{PolariscopeLamp::Collimated, "collimated"}, {PolariscopeLamp::Diffuse, "diffuse"}}}};

// A job's `polariscope` (JSON, described once in polariscopeSettingsSchema()).
struct PolariscopeSettings {
    int angles = 36;           // turntable positions over half a turn (the view repeats every 180 deg)
    uint64_t photons = 20000;  // per position
    int pictureSize = 160;     // pixels across each position's view from above (0: no pictures)
    PolariscopeLamp lamp = PolariscopeLamp::Collimated;
};

const settings::Schema<PolariscopeSettings>& polariscopeSettingsSchema();

// One turntable position: the share of the light leaving the stone upward that the analyser passes.
struct PolariscopeReading {
    double angleDeg = 0;  // the stone turned this far (counter-clockwise seen from above)
    uint64_t upward = 0;  // photons that left the stone upward
    uint64_t passed = 0;  // of those, passed by the analyser (each with its Malus share, drawn)
    // With a picture size n: the passed photons by where they left the stone, seen from above with the stone
    // turned, n x n cells over a square of the stone's largest horizontal radius, row 0 at the top (+y).
    std::vector<uint32_t> seen;
    double share() const { return upward ? double(passed) / double(upward) : 0; }
    double shareStderr() const;
};

// What a gemmologist reports of the turn: the field stays dark, blinks, or stays light.
enum class PolariscopeReaction { StaysDark, Blinks, StaysLight };
inline constexpr NameTable<PolariscopeReaction, 3> kPolariscopeReactionNames{
    {{{PolariscopeReaction::StaysDark, "stays_dark"},
      {PolariscopeReaction::Blinks, "blinks"},
      {PolariscopeReaction::StaysLight, "stays_light"}}}};

struct Polariscope {
    std::vector<PolariscopeReading> readings;
    // The turntable angles where the stone goes dark, over a whole turn: it blinks when its darkest reading
    // is under half the brightest, and then goes dark at each reading that is the least within 45 deg either
    // way and nearer the darkest than the brightest (each 5 standard errors under the brightest). Otherwise
    // it stays dark when every reading passes under kStaysDarkShare, and light when not.
    std::vector<double> darkAnglesDeg;
    PolariscopeReaction reaction = PolariscopeReaction::StaysDark;
    bool blinks() const { return reaction == PolariscopeReaction::Blinks; }
};

// Our line between a field that stays dark and one that stays light: a tenth of the upward light, well above
// what an isotropic cube leaks under a light box (about 1 %, docs/optics.md) and below a faceted stone's
// reflections (a diamond brilliant about 40 %).
inline constexpr double kStaysDarkShare = 0.1;

// `settings` gives the stone's material, optic axis, seed and threads; the instrument sets the rest: the lamp's
// light travelling up, a polariser at -angle (the stone turned by angle), the analyser crossed above it, and
// polarisation on. Photon i of each position draws from Rng(seed, i) and the analyser from a stream of its own,
// so the readings are the same at any thread count. Adds each position's photons to control->done() (the caller
// starts the phase) and stops early when cancelled.
Polariscope polariscope(const Stone& stone, const TraceSettings& settings, const PolariscopeSettings& p,
                        RunControl* control = nullptr);

nlohmann::json toJson(const Polariscope& p);

}  // namespace facetlight
