#include "optics/light_model.h"

#include <algorithm>
#include <cmath>

#include "util/error.h"

namespace facetlight {
namespace {

// Photons start at a point light and are traced in single precision: from further than this the error of a
// float position (6e-8 of the distance) nears a thousandth of the stone, and the light a collimated one.
constexpr double kMaxPointLightRadii = 1e4;

// An orthonormal basis around a unit vector (Duff et al., "Building an orthonormal basis, revisited",
// JCGT 6(1), 2017).
void basis(const Vec3& n, Vec3& u, Vec3& v) {
    const double sign = std::copysign(1.0, n.z);
    const double a = -1.0 / (sign + n.z);
    const double b = n.x * n.y * a;
    u = {1.0 + sign * n.x * n.x * a, sign * b, -sign * n.x};
    v = {b, sign + n.y * n.y * a, -n.y};
}

// The stone tilted about x by `tilt` is the light rotated by -tilt about x.
Vec3 untilt(const Vec3& p, double cosT, double sinT) {
    return {p.x, p.y * cosT + p.z * sinT, -p.y * sinT + p.z * cosT};
}

// A uniform point (x, y) in the unit disc by rejection, which needs no trigonometry; its squared radius r2 is
// itself uniform in (0, 1), and (x, y) / sqrt(r2) is a uniform direction.
struct DiscPoint {
    double x, y, r2;
};
DiscPoint unitDisc(Rng& rng) {
    for (;;) {
        const double x = 2 * rng.uniformDouble() - 1, y = 2 * rng.uniformDouble() - 1, r2 = x * x + y * y;
        if (r2 < 1 && r2 > 0) return {x, y, r2};
    }
}

// A direction at cos(theta) from `axis`, in the azimuth of the disc point q.
Vec3 around(const Vec3& axis, double cosTheta, const DiscPoint& q) {
    Vec3 u, v;
    basis(axis, u, v);
    const double sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta)), s = sinTheta / std::sqrt(q.r2);
    return u * (q.x * s) + v * (q.y * s) + axis * cosTheta;
}

}  // namespace

LightModel::LightModel(const LightSettings& s, const Stone& stone) : kind_(s.model) {
    if (stone.vertices.empty()) throw Error("stone '" + stone.name + "' has no vertices");
    center_ = stone.bounds.center();
    for (const Vec3& p : stone.vertices) radius_ = std::max(radius_, length(p - center_));
    cosTilt_ = std::cos(radians(s.tiltDeg));
    sinTilt_ = std::sin(radians(s.tiltDeg));

    switch (kind_) {
        case LightModelKind::Collimated: {
            dir_ = untilt(normalizeAnySize(s.direction), cosTilt_, sinTilt_);
            basis(dir_, u_, v_);
            // The tightest disc about the centre of the silhouette's bounding rectangle.
            double uLo = INFINITY, uHi = -INFINITY, vLo = INFINITY, vHi = -INFINITY, front = INFINITY;
            for (const Vec3& p : stone.vertices) {
                uLo = std::min(uLo, dot(p, u_));
                uHi = std::max(uHi, dot(p, u_));
                vLo = std::min(vLo, dot(p, v_));
                vHi = std::max(vHi, dot(p, v_));
                front = std::min(front, dot(p, dir_));
            }
            const double cu = 0.5 * (uLo + uHi), cv = 0.5 * (vLo + vHi);
            for (const Vec3& p : stone.vertices) {
                discRadius_ = std::max(discRadius_, std::hypot(dot(p, u_) - cu, dot(p, v_) - cv));
            }
            discRadius_ *= 1 + 1e-6;
            discCenter_ = u_ * cu + v_ * cv + dir_ * (front - 0.01 * radius_);
            break;
        }
        case LightModelKind::Hemisphere: {
            const double sinShadow = std::sin(radians(s.headShadowDeg));
            sin2Shadow_ = sinShadow * sinShadow;
            cosShadow_ = std::cos(radians(s.headShadowDeg));
            cosineSky_ = s.sky == SkyKind::Cosine;
            break;
        }
        case LightModelKind::Point: {
            position_ = untilt(s.position, cosTilt_, sinTilt_);
            const double d = length(center_ - position_);
            if (!(d > radius_ * 1.001)) {
                throw Error("light.position",
                            "light.position must lie outside the stone's bounding sphere (centre " +
                                std::to_string(center_.z) + " on the z axis, radius " +
                                std::to_string(radius_) + ")");
            }
            if (!(d <= kMaxPointLightRadii * radius_)) {
                throw Error("light.position",
                            "light.position must lie within " + std::to_string(int(kMaxPointLightRadii)) +
                                " stone radii of the stone (a distant light is the collimated model)");
            }
            cosCone_ = std::sqrt(1 - (radius_ / d) * (radius_ / d));
            dir_ = normalize(center_ - position_);
            break;
        }
    }
}

LightRay LightModel::sample(Rng& rng) const {
    switch (kind_) {
        case LightModelKind::Collimated: {
            const DiscPoint q = unitDisc(rng);
            return {discCenter_ + u_ * (discRadius_ * q.x) + v_ * (discRadius_ * q.y), dir_};
        }
        case LightModelKind::Hemisphere: {
            // The disc below fires each direction through the stone's projected area, which weights it by
            // cos(theta) by itself. A uniform dome therefore draws directions uniform in solid angle over the
            // upper hemisphere less the head cone (cos(theta) uniform); the cosine sky draws them
            // cosine-weighted as well (sin^2(theta) uniform). The azimuth is that of the disc point a.
            const DiscPoint a = unitDisc(rng);
            double cosTheta, sinTheta;
            if (cosineSky_) {
                const double sin2 = sin2Shadow_ + (1 - sin2Shadow_) * a.r2;
                cosTheta = std::sqrt(1 - sin2), sinTheta = std::sqrt(sin2);
            } else {
                cosTheta = cosShadow_ * (1 - a.r2);
                sinTheta = std::sqrt(std::max(0.0, 1 - cosTheta * cosTheta));
            }
            const double s = sinTheta / std::sqrt(a.r2);
            const Vec3 dir = -untilt({a.x * s, a.y * s, cosTheta}, cosTilt_, sinTilt_);
            Vec3 u, v;
            basis(dir, u, v);
            const DiscPoint b = unitDisc(rng);
            return {center_ - dir * (1.01 * radius_) + u * (radius_ * b.x) + v * (radius_ * b.y), dir};
        }
        case LightModelKind::Point: {
            const DiscPoint q = unitDisc(rng);
            return {position_, around(dir_, 1 - q.r2 * (1 - cosCone_), q)};
        }
    }
    return {};
}

}  // namespace facetlight
