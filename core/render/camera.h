#pragma once
// A pinhole camera aimed at the stone, placed by elevation, azimuth and distance (render_settings.h). At
// elevation 90 it looks straight down with +y up in the picture; lowering the elevation swings it toward -y
// (the viewer's side), and the azimuth turns it about the vertical.
#include "geometry/geometry.h"
#include "render/render_settings.h"

namespace facetlight {

class Camera {
  public:
    // `target` is the point looked at and `scale` the length that `settings.distance` is measured in (the
    // girdle diameter), both in world coordinates.
    Camera(const CameraSettings& settings, const Vec3& target, double scale, int width, int height);

    const Vec3& position() const { return position_; }
    const Vec3& forward() const { return forward_; }
    // Unit direction through the film point (px, py) in pixels, y down (pixel centres at +0.5).
    Vec3 direction(double px, double py) const;

  private:
    Vec3 position_, forward_, right_, up_;
    double halfHeight_ = 0;  // tan(fov / 2)
    double invHeight_ = 0, halfWidthPixels_ = 0, halfHeightPixels_ = 0;
};

}  // namespace facetlight
