#pragma once
// The viewer in the world and what each direction shows them (docs/physics.md, "Viewer figures"). The world's
// origin is the stone's girdle centre, +z up; the eye is straight above at the viewing distance, its head a dark
// disc around it and its shoulders a dark disc below it toward -y (the viewer's side). A pose of the motion
// turns the stone about its own axis, then tilts it about the world's x axis (toward and away from the viewer).
#include <cstdint>

#include "geometry/geometry.h"
#include "optics/viewer_settings.h"

namespace facetlight {

// One position of the motion: the stone turned by `turnDeg` about its axis (stone z), then tilted by `tiltDeg`
// about the world's x axis.
class StonePose {
  public:
    StonePose(double tiltDeg, double turnDeg);
    Vec3 toWorld(const Vec3& v) const;
    Vec3 toStone(const Vec3& v) const;

  private:
    double cosTilt_, sinTilt_, cosTurn_, sinTurn_;
};

// What a direction out of the stone meets.
enum class Seen : uint8_t { Sky, Viewer, Background, Trapped };

class Observer {
  public:
    // `meshPerMm`: mesh units per millimetre (the stone's girdle diameter over its size in mm).
    Observer(const ViewerSettings& settings, double meshPerMm);

    const Vec3& eye() const { return eye_; }  // world
    double pupilRadius() const { return pupilRadius_; }
    // What world direction `dir` (unit, from the stone) meets in the office, and its radiance relative to the
    // dome's zenith.
    Seen office(const Vec3& dir, double& radiance) const;
    // Whether world direction `dir` (unit, from the stone) meets the viewer's head.
    bool head(const Vec3& dir) const { return dot(dir, toEye_) >= cosHead_; }
    // Whether world direction `dir` (unit, from the stone) points within the spot set-up's viewing cone.
    bool inViewingCone(const Vec3& dir) const { return dot(dir, toEye_) >= cosViewingCone_; }
    const Vec3& toEye() const { return toEye_; }

  private:
    Vec3 eye_, toEye_, toShoulders_;
    double pupilRadius_;
    double cosHead_, cosShoulders_;  // cos of the discs' angular radii seen from the stone (2: none)
    DomeProfile dome_;
    double background_;
    double cosViewingCone_;
};

}  // namespace facetlight
