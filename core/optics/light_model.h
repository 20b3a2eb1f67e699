#pragma once
// Where photons come from. Each model aims its photons at a disc that covers the stone's silhouette as seen
// along the photon's direction, so few are wasted on empty space; every photon drawn counts in `photons`.
#include "geometry/geometry.h"
#include "optics/light_settings.h"
#include "stone/stone.h"
#include "util/random.h"

namespace facetlight {

struct LightRay {
    Vec3 origin;
    Vec3 direction;  // unit, direction of travel
};

class LightModel {
  public:
    // Throws Error when the settings cannot light this stone (a point source inside its bounding sphere).
    LightModel(const LightSettings& settings, const Stone& stone);

    LightRay sample(Rng& rng) const;

    // The smallest sphere around the bounds centre holding every vertex.
    Vec3 sphereCenter() const { return center_; }
    double sphereRadius() const { return radius_; }
    // Collimated: the radius of the disc the photons cross, so each of N photons carries pi r^2 / N of a unit
    // beam irradiance (the renderer's photon power).
    double discRadius() const { return discRadius_; }
    // Collimated: the one direction every photon travels in.
    bool collimated() const { return kind_ == LightModelKind::Collimated; }
    Vec3 direction() const { return dir_; }
    // Collimated: the disc the photons start on; sample() draws a uniform point q of the unit disc and
    // starts at center + u * (radius * q.x) + v * (radius * q.y), in that order of operations.
    struct Disc {
        Vec3 center, u, v;
        double radius;
    };
    Disc disc() const { return {discCenter_, u_, v_, discRadius_}; }

  private:
    LightModelKind kind_;
    Vec3 center_;
    double radius_ = 0;
    Vec3 dir_, u_, v_;       // collimated: direction and the disc's axes; point: the cone's axis
    Vec3 discCenter_;        // collimated: centre of the silhouette disc, in front of the stone
    double discRadius_ = 0;  // collimated
    double sin2Shadow_ = 0;  // hemisphere: sin^2 and cos of the head-shadow half-angle
    double cosShadow_ = 1;
    bool cosineSky_ = false;  // hemisphere: the cos(theta) sky instead of the uniform dome
    double cosTilt_ = 1, sinTilt_ = 0;
    Vec3 position_;       // point, tilted into the stone's frame
    double cosCone_ = 1;  // point: cone of directions toward the bounding sphere
};

}  // namespace facetlight
