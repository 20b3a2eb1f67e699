#pragma once
// How a person looks at a stone (docs/physics.md, "Viewer figures"): the viewer, the two lighting set-ups and
// the motion averaged over. Apart from the algorithms (viewer/office_view.h, viewer/spot_fire.h), each setting
// described once in its table: JSON (a job's "viewer"), checks, CLI flags and the API schema follow from it.
// The defaults and their sources: docs/physics.md, "Viewer figures".
#include <cstdint>

#include <nlohmann/json.hpp>

#include "settings/settings_schema.h"
#include "util/name_table.h"

namespace facetlight {

// The radiance of the office's diffuse dome against the angle theta from the zenith, relative to the zenith:
// uniform 1, the CIE standard overcast sky (1 + 2 cos theta) / 3, or cos theta (ceiling lights overhead, the
// walls dimmer toward the horizon).
enum class DomeProfile { Uniform, Overcast, Cosine };
inline constexpr NameTable<DomeProfile, 3> kDomeProfileNames{{{{DomeProfile::Uniform, "uniform"},
                                                               {DomeProfile::Overcast, "overcast"},
                                                               {DomeProfile::Cosine, "cosine"}}}};

// The office: a diffuse dome above a grey tray, the viewer's head and shoulders dark against it; traced from
// the viewer's eye (brightness, contrast, scintillation, windowing, extinction).
struct OfficeSettings {
    DomeProfile dome = DomeProfile::Cosine;
    double trayAlbedo = 0.18;  // below the horizon: a matt grey tray lit by the dome
    uint64_t points = 10000;   // face-up points, each seen from every position of the motion
};

// Small lamps in a dark room, traced from the lamps (fire).
struct SpotSettings {
    int lamps = 6;               // evenly spread in azimuth; those behind the viewer are hidden
    double elevationDeg = 50;    // of every lamp above the horizon
    double viewingConeDeg = 30;  // light leaving within this angle of the direction to the viewer is seen
    uint64_t photons = 300000;   // over all lamps and positions
};

// Named viewing set-ups: every setting at the set-up's value, which the settings given beside it then change.
// standard: the defaults below; dome: Hemphill et al. 1998's light for brightness, a uniform dome with no
// viewer in it and nothing lit below; close: a close look at 150 mm, where the viewer's head hides more.
enum class ViewerSetUp { Standard, Dome, Close };
inline constexpr NameTable<ViewerSetUp, 3> kViewerSetUpNames{
    {{{ViewerSetUp::Standard, "standard"}, {ViewerSetUp::Dome, "dome"}, {ViewerSetUp::Close, "close"}}}};

struct ViewerSettings {
    ViewerSetUp setUp = ViewerSetUp::Standard;
    bool enabled = true;
    double distanceMm = 250;       // from the eye to the stone
    double pupilMm = 4;            // the eye's pupil diameter
    double headWidthMm = 160;      // the viewer's head: a disc this wide around the eye
    double shoulderWidthMm = 400;  // the viewer's shoulders: a disc this wide ...
    double shoulderDropMm = 300;   // ... this far below the eye toward the viewer's side ...
    double shoulderBackMm = 100;   // ... and this much further from the stone
    double rockDeg = 30;           // the stone rocked toward and away from the viewer up to this angle ...
    int tilts = 7;                 // ... in this many tilts from -rockDeg to +rockDeg ...
    int azimuths = 4;              // ... at this many turns about its own axis (turnDeg);
    double sparkleStepDeg = 1;     // each tilt also seen this much further on: what switches, sparkles
    OfficeSettings office;
    SpotSettings spot;

    // The set-up's settings, before any other is changed.
    static ViewerSettings forSetUp(ViewerSetUp setUp);
    int positions() const { return tilts * azimuths; }
    double tiltDeg(int tilt) const;  // the k-th tilt, from -rockDeg to +rockDeg
    // The a-th turn about the stone's axis, a (360 + 45) / azimuths deg: spread over the whole circle and, for
    // the eight-fold round brilliant, evenly over its 45-deg repeat.
    double turnDeg(int azimuth) const;
    void validate() const;  // throws Error naming the field ("viewer.tilts")
    static ViewerSettings fromJson(const nlohmann::json& j);
};

constexpr uint64_t kMaxViewerPoints = 10'000'000;
constexpr uint64_t kMaxViewerPhotons = 1'000'000'000;
constexpr int kMaxViewerTilts = 41;
constexpr int kMaxViewerAzimuths = 16;

// Its path is "viewer", where a job holds it.
const settings::Schema<ViewerSettings>& viewerSettingsSchema();
nlohmann::json toJson(const ViewerSettings& s);

}  // namespace facetlight
