#include "optics/viewer_settings.h"

#include <string>

#include "util/error.h"

namespace facetlight {

using namespace settings;

namespace {

const Schema<OfficeSettings>& officeSchema() {
    static const Schema<OfficeSettings> schema({
        choice("dome", &OfficeSettings::dome, kDomeProfileNames,
               {"--office-dome",
                "Office: the dome's radiance from the zenith down (uniform; overcast, the CIE sky (1 + 2 cos "
                "theta) / 3; cosine)"}),
        number("tray_albedo", &OfficeSettings::trayAlbedo, {.lo = 0, .hi = 1},
               {"--office-tray", "Office: the albedo of the matt tray below the stone, lit by the dome"}),
        count("points", &OfficeSettings::points, 100, kMaxViewerPoints,
              {"--office-points", "Office: face-up points, each seen from every position of the motion"}),
    });
    return schema;
}

const Schema<SpotSettings>& spotSchema() {
    static const Schema<SpotSettings> schema({
        count("lamps", &SpotSettings::lamps, 1, 64, {"--spot-lamps", "Spot: lamps, evenly spread in azimuth"}),
        number("elevation_deg", &SpotSettings::elevationDeg, {.lo = 0, .hi = 90, .openLo = true},
               {"--spot-elevation", "Spot: the lamps' elevation above the horizon", "degrees"}),
        number("viewing_cone_deg", &SpotSettings::viewingConeDeg, {.lo = 0, .hi = 90, .openLo = true},
               {"--spot-viewing-cone",
                "Spot: light leaving within this angle of the direction to the viewer counts as seen", "degrees"}),
        count("photons", &SpotSettings::photons, 1000, kMaxViewerPhotons,
              {"--spot-photons", "Spot: photons over all lamps and positions"}),
    });
    return schema;
}

// The set-up's row comes first: reading it sets every setting, and the rows after it change them.
Field<ViewerSettings> setUpField() {
    Field<ViewerSettings> f =
        choice("set_up", &ViewerSettings::setUp, kViewerSetUpNames,
               {"--view",
                "Viewer: the viewing set-up every other --view... and --office/--spot flag changes (standard; "
                "dome, Hemphill 1998's uniform dome with no viewer; close, at 150 mm)"});
    const auto readChoice = f.read;
    f.read = [readChoice](ViewerSettings& s, const nlohmann::json& j, const std::string& path) {
        ViewerSettings picked;
        readChoice(picked, j, path);
        s = ViewerSettings::forSetUp(picked.setUp);
    };
    return f;
}

}  // namespace

ViewerSettings ViewerSettings::forSetUp(ViewerSetUp setUp) {
    ViewerSettings s;
    s.setUp = setUp;
    switch (setUp) {
        case ViewerSetUp::Standard:
            break;
        case ViewerSetUp::Dome:
            s.headWidthMm = 0;
            s.shoulderWidthMm = 0;
            s.office.dome = DomeProfile::Uniform;
            s.office.trayAlbedo = 0;
            break;
        case ViewerSetUp::Close:
            s.distanceMm = 150;
            break;
    }
    return s;
}

const Schema<ViewerSettings>& viewerSettingsSchema() {
    static const Schema<ViewerSettings> schema(
        {
            setUpField(),
            boolean("enabled", &ViewerSettings::enabled,
                    {"--no-view", "Skip the viewer figures (brightness, fire, contrast, scintillation, ...)"}),
            number("distance_mm", &ViewerSettings::distanceMm, {.lo = 20, .hi = 10000},
                   {"--view-distance", "Viewer: from the eye to the stone", "mm"}),
            number("pupil_mm", &ViewerSettings::pupilMm, {.lo = 0, .hi = 20},
                   {"--view-pupil", "Viewer: the pupil's diameter", "mm"}),
            number("head_width_mm", &ViewerSettings::headWidthMm, {.lo = 0, .hi = 1000},
                   {"--view-head", "Viewer: the head's width (a dark disc around the eye)", "mm"}),
            number("shoulder_width_mm", &ViewerSettings::shoulderWidthMm, {.lo = 0, .hi = 2000},
                   {"--view-shoulders", "Viewer: the shoulders' width (a dark disc below the head)", "mm"}),
            number("shoulder_drop_mm", &ViewerSettings::shoulderDropMm, {.lo = 0, .hi = 2000},
                   {"--view-shoulder-drop",
                    "Viewer: from the eye down to the shoulders' centre, toward the viewer's side", "mm"}),
            number("shoulder_back_mm", &ViewerSettings::shoulderBackMm, {.lo = 0, .hi = 2000},
                   {"--view-shoulder-back", "Viewer: how much further the shoulders are from the stone than the eye",
                    "mm"}),
            number("rock_deg", &ViewerSettings::rockDeg, {.lo = 0, .hi = 45},
                   {"--view-rock", "Viewer: the stone rocked toward and away from the viewer up to this angle",
                    "degrees"}),
            count("tilts", &ViewerSettings::tilts, 1, kMaxViewerTilts,
                  {"--view-tilts", "Viewer: tilts of the rock, from -rock to +rock"}),
            count("azimuths", &ViewerSettings::azimuths, 1, kMaxViewerAzimuths,
                  {"--view-azimuths", "Viewer: turns of the stone about its own axis"}),
            number("sparkle_step_deg", &ViewerSettings::sparkleStepDeg, {.lo = 0, .hi = 10, .openLo = true},
                   {"--view-sparkle-step",
                    "Viewer: each tilt is also seen this much further on; scintillation is what switches between "
                    "the two",
                    "degrees"}),
            object("office", &ViewerSettings::office, officeSchema()),
            object("spot", &ViewerSettings::spot, spotSchema()),
        },
        [](const ViewerSettings& s, const std::string& path) {
            if (s.rockDeg > 0 && s.tilts < 2) {
                const std::string tilts = fieldPath(path, "tilts");
                throw Error(tilts, tilts + " must be at least 2 when the stone rocks (" +
                                       fieldPath(path, "rock_deg") + " above 0)");
            }
        });
    return schema;
}

double ViewerSettings::tiltDeg(int tilt) const {
    return tilts < 2 ? 0.0 : -rockDeg + 2 * rockDeg * tilt / (tilts - 1);
}

double ViewerSettings::turnDeg(int azimuth) const {
    return azimuth * (360.0 + 45.0) / azimuths;
}

void ViewerSettings::validate() const {
    fromJson(toJson(*this));
}

ViewerSettings ViewerSettings::fromJson(const nlohmann::json& j) {
    return viewerSettingsSchema().read(j, "viewer");
}

nlohmann::json toJson(const ViewerSettings& s) {
    return viewerSettingsSchema().write(s);
}

}  // namespace facetlight
