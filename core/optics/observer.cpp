#include "optics/observer.h"

#include <cmath>

namespace facetlight {
namespace {

// cos of the angular radius of a disc of `width` at `distance`, seen from the stone; 2 (never met) when it has
// no width.
double cosDisc(double width, double distance) {
    if (width <= 0) return 2;
    const double r = width / 2;
    return r >= distance ? -1.0 : std::sqrt(1 - (r / distance) * (r / distance));
}

// The irradiance the dome gives a horizontal plane, integral of L(theta) cos(theta) over the hemisphere, with
// the zenith's radiance 1: pi (uniform), 7 pi / 9 (overcast), 2 pi / 3 (cosine).
double domeIrradiance(DomeProfile dome) {
    switch (dome) {
        case DomeProfile::Uniform:
            return M_PI;
        case DomeProfile::Overcast:
            return 7 * M_PI / 9;
        case DomeProfile::Cosine:
            return 2 * M_PI / 3;
    }
    return M_PI;
}

}  // namespace

StonePose::StonePose(double tiltDeg, double turnDeg)
    : cosTilt_(std::cos(radians(tiltDeg))),
      sinTilt_(std::sin(radians(tiltDeg))),
      cosTurn_(std::cos(radians(turnDeg))),
      sinTurn_(std::sin(radians(turnDeg))) {}

Vec3 StonePose::toWorld(const Vec3& v) const {
    const Vec3 t{v.x * cosTurn_ - v.y * sinTurn_, v.x * sinTurn_ + v.y * cosTurn_, v.z};
    return {t.x, t.y * cosTilt_ - t.z * sinTilt_, t.y * sinTilt_ + t.z * cosTilt_};
}

Vec3 StonePose::toStone(const Vec3& v) const {
    const Vec3 t{v.x, v.y * cosTilt_ + v.z * sinTilt_, -v.y * sinTilt_ + v.z * cosTilt_};
    return {t.x * cosTurn_ + t.y * sinTurn_, -t.x * sinTurn_ + t.y * cosTurn_, t.z};
}

Observer::Observer(const ViewerSettings& s, double meshPerMm)
    : eye_(0, 0, s.distanceMm * meshPerMm),
      toEye_(0, 0, 1),
      pupilRadius_(s.pupilMm / 2 * meshPerMm),
      dome_(s.office.dome),
      background_(s.office.trayAlbedo * domeIrradiance(s.office.dome) / M_PI),
      cosViewingCone_(std::cos(radians(s.spot.viewingConeDeg))) {
    const Vec3 shoulders(0, -s.shoulderDropMm, s.distanceMm + s.shoulderBackMm);
    toShoulders_ = normalize(shoulders);
    cosHead_ = cosDisc(s.headWidthMm, s.distanceMm);
    cosShoulders_ = cosDisc(s.shoulderWidthMm, length(shoulders));
}

Seen Observer::office(const Vec3& dir, double& radiance) const {
    radiance = 0;
    if (dir.z < 0) {
        radiance = background_;
        return Seen::Background;
    }
    if (dot(dir, toEye_) >= cosHead_ || dot(dir, toShoulders_) >= cosShoulders_) return Seen::Viewer;
    switch (dome_) {
        case DomeProfile::Uniform:
            radiance = 1;
            break;
        case DomeProfile::Overcast:
            radiance = (1 + 2 * dir.z) / 3;
            break;
        case DomeProfile::Cosine:
            radiance = dir.z;
            break;
    }
    return Seen::Sky;
}

}  // namespace facetlight
