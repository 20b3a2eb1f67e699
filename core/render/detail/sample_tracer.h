#pragma once
// Inside the renderers (not for use outside core/render): one camera sample's tree of rays through the stone,
// written once for every picture that looks at the stone through a camera. What lies around the stone (the
// studio and its floor, or the fire picture's spotlight) is the Surroundings policy: the light arriving along
// a ray that left the stone or missed it.
#include <algorithm>
#include <array>
#include <cmath>

#include "optics/fresnel.h"
#include "render/render_settings.h"
#include "scene/scene.h"
#include "util/random.h"

namespace facetlight::detail {

// A branch of the ray tree is followed both ways at an interface while both weights stay above this; below
// it one way is chosen with the Fresnel probabilities (unbiased, and the tree stays small).
constexpr double kBranchWeight = 0.05;

struct Branch {
    Vec3 origin, dir;
    double weight;
    int depth;
    bool inside;
    // Whether the path went through the stone with a wavelength-dependent index. Until it has, its light does
    // not depend on the sample's wavelength: it is counted as `white`, free of colour noise.
    bool spectral;
};

// Surroundings, for a ray from `origin` along `dir` (stone frame) that meets the stone at distance t:
//   bool stoneFirst(origin, dir, t): whether the stone is met before anything around it (a floor);
//   Vec3 radiance(origin, dir, colour, weight, rng): the light, in the sample's colour and times the branch's
//   weight, arriving along a ray that does not go on into the stone.
template <class Surroundings>
class SampleTracer {
  public:
    SampleTracer(const Scene& scene, int maxDepth, Surroundings& surroundings, Rng& rng)
        : scene_(scene), maxDepth_(maxDepth), surroundings_(surroundings), rng_(rng) {}

    // The light along a camera ray at refractive index n, in `colour` once the path depends on the
    // wavelength and in `white` until then.
    Vec3 trace(const Vec3& origin, const Vec3& dir, double n, const Vec3& colour, const Vec3& white) {
        const double diameter = scene_.diameter();
        std::array<Branch, 2 * kMaxDepth + 2> stack;
        int top = 0;
        stack[top++] = {origin, dir, 1.0, 0, false, false};
        Vec3 sum;
        while (top > 0) {
            const Branch b = stack[--top];
            SurfaceHit hit;
            if (!b.inside) {
                if (!scene_.enter(Vec3f(b.origin), Vec3f(b.dir), hit) ||
                    !surroundings_.stoneFirst(b.origin, b.dir, double(hit.t))) {
                    sum +=
                        surroundings_.radiance(b.origin, b.dir, b.spectral ? colour : white, b.weight, rng_);
                    continue;
                }
                if (b.depth >= maxDepth_) continue;
                const Vec3 p = b.origin + b.dir * double(hit.t);
                const Vec3f& nf = scene_.normal(hit.facet);
                const Vec3 normal{nf.x, nf.y, nf.z};
                const double cosI = std::clamp(-dot(b.dir, normal), 0.0, 1.0);
                const double eta = 1 / n;
                const FresnelResult fr = fresnel(float(cosI), float(eta));
                const Vec3 reflected = b.dir + normal * (2 * cosI);
                const Vec3 refracted = normalize(b.dir * eta + normal * (eta * cosI - fr.cosT));
                split(stack, top, b, fr.reflectance,
                      {p + reflected * (1e-6 * diameter), reflected, 0, 0, false, false},
                      {p, refracted, 0, 0, true, false});
            } else {
                if (!scene_.leave(Vec3f(b.origin), Vec3f(b.dir), hit) || b.depth >= maxDepth_) continue;
                const Vec3 p = b.origin + b.dir * double(hit.t);
                const Vec3f& nf = scene_.normal(hit.facet);
                const Vec3 normal{nf.x, nf.y, nf.z};
                const double cosI = std::clamp(dot(b.dir, normal), 0.0, 1.0);
                const FresnelResult fr = fresnel(float(cosI), float(n));
                const Vec3 reflected = b.dir - normal * (2 * cosI);
                if (fr.totalInternal) {
                    stack[top++] = {p, reflected, b.weight, b.depth + 1, true, b.spectral};
                    continue;
                }
                const Vec3 out = normalize(b.dir * n - normal * (n * cosI - fr.cosT));
                split(stack, top, b, fr.reflectance, {p, reflected, 0, 0, true, false},
                      {p + out * (1e-6 * diameter), out, 0, 0, false, false});
            }
        }
        return sum;
    }

  private:
    // Pushes the reflected and transmitted continuations of b, both when they carry enough weight, else one
    // chosen with probability R (reflection) or 1 - R.
    template <size_t N>
    void split(std::array<Branch, N>& stack, int& top, const Branch& b, double r, Branch reflected,
               Branch transmitted) {
        reflected.depth = transmitted.depth = b.depth + 1;
        const bool dispersive = scene_.dispersive();
        reflected.spectral = b.spectral || (reflected.inside && dispersive);
        transmitted.spectral = b.spectral || (transmitted.inside && dispersive);
        if (b.weight * std::min(r, 1 - r) > kBranchWeight && top + 2 <= int(N)) {
            reflected.weight = b.weight * r;
            transmitted.weight = b.weight * (1 - r);
            stack[top++] = reflected;
            stack[top++] = transmitted;
        } else {
            Branch& chosen = rng_.uniformDouble() < r ? reflected : transmitted;
            chosen.weight = b.weight;
            stack[top++] = chosen;
        }
    }

    const Scene& scene_;
    int maxDepth_;
    Surroundings& surroundings_;
    Rng& rng_;
};

}  // namespace facetlight::detail
