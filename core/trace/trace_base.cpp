#include "trace/trace_base.h"

#include <algorithm>
#include <cmath>

#include "optics/fresnel.h"
#include "optics/material.h"
#include "trace/fire_trace.h"

namespace facetlight {

TraceBase::TraceBase(const Scene& scene, const TraceSettings& settings)
    : scene_(scene), settings_(settings), up_(scene.up()) {
    for (const Facet& f : scene.stone().facets)
        crownSide_.push_back(f.region == Region::Table || f.region == Region::Crown);
    const double headShadowDeg = scene.lightSettings().headShadowDeg;
    cosHeadShadow_ = headShadowDeg > 0 ? float(std::cos(radians(headShadowDeg))) : 2.0f;
    for (int c = 0; c < kConeCount; ++c) cosCone_[c] = float(std::cos(radians(kConeDegrees[c])));
    if (const std::optional<double> deg = scene.lightSettings().polarizerDeg) {
        // A tilt turns the stone about x (LightSettings::tiltDeg): the world's horizontal y is cross(up, x).
        const Vec3f x(1, 0, 0), y = normalize(cross(up_, x));
        const double a = radians(*deg);
        polarizer_ = x * float(std::cos(a)) + y * float(std::sin(a));
    }
    const Material& material = scene.material();
    birefringent_ = polarized() && material.optic() != Optic::Isotropic;
    biaxial_ = birefringent_ && material.optic() == Optic::Biaxial;
    if (biaxial_) {
        opticAxis_ = settings.opticAxis.direction();
        principalAxes_ = settings.opticAxis.principalAxes();
        const std::array<double, 3> d = material.principalIndices(Material::kSodiumD);
        birefringenceD_ = float(d[2] - d[1]);
        alphaOffsetD_ = float(d[0] - d[1]);
        coherentSin2_ = -1;  // no cone: 1 - c^2 is never below it
    } else if (birefringent_) {
        opticAxis_ = settings.opticAxis.direction();
        const std::array<double, 3> d = material.principalIndices(Material::kSodiumD);
        birefringenceD_ = float(d[2] - d[0]);
        // n_e(theta) - n_o ~ (n_e - n_o) sin^2 theta near the axis (Born & Wolf eq. 15.3.(21)): half a wave of
        // 550 nm over the girdle diameter.
        coherentSin2_ = 275.0 / (std::abs(d[2] - d[0]) * settings.sizeMm * 1e6);
    }
    if (const std::optional<AbsorptionSpectrum>& a = material.absorption()) {
        absorbs_ = a->absorbs();
        mixedAbsorption_ = !birefringent_ && material.optic() == Optic::Uniaxial;
        trichroic_ = biaxial_ && absorbs_ && a->trichroic();
        mmPerUnit_ = settings.sizeMm / scene.diameter();
    }
    if (scene.light().collimated() && !scene.dispersive() && !polarized())
        fixedEntry_ = fixedEntriesAt(scene.fixedIndex());
    if (settings.fire.enabled && scene.light().collimated() && !birefringent_) {
        const std::array<FireBand, kFireBands> bands = fireBands(scene);
        for (int k = 0; k < kFireBands; ++k) {
            bandEntryIndex_[k] = bands[k].index;
            bandEntry_[k] = fixedEntriesAt(bands[k].index);
        }
    }
}

std::vector<TraceBase::FixedEntry> TraceBase::fixedEntriesAt(float n) const {
    // The same float operations as PhotonWalker::enter (and enterPolarized), so a photon's fate is bit for
    // bit the same.
    const Vec3f d(scene_.light().direction());
    const float eta = 1.0f / n;
    std::vector<FixedEntry> entries;
    for (const Vec3f& normal : scene_.normals()) {
        const float cosI = std::clamp(-dot(d, normal), 0.0f, 1.0f);
        FixedEntry e{0, reflectOff(d, normal, cosI), {}, {}};
        float cosT;
        if (polarized()) {
            const FacetMeeting<float> m = meetFacet(sourcePolarization(d), d, normal, cosI, eta);
            e.reflectance = m.waves.reflected.share(m.stokes);
            e.inside = {m.waves.refracted.apply(m.stokes), toVec3f(m.s)};
            cosT = m.waves.cosT;
        } else {
            const FresnelResult fr = fresnel(cosI, eta);
            e.reflectance = fr.reflectance;
            cosT = fr.cosT;
        }
        e.refracted = refractIn(d, normal, eta, cosI, cosT);
        entries.push_back(e);
    }
    return entries;
}

float TraceBase::principalIndex(int axis, double wavelengthNm) const {
    const double nm = scene_.dispersive() ? wavelengthNm : Material::kSodiumD;
    return float(scene_.material().principalIndex(axis, nm));
}

float TraceBase::absorption(float wavelengthNm) const {
    if (!absorbs_) return 0;
    const AbsorptionSpectrum& a = *scene_.material().absorption();
    const double o = a.ordinary(wavelengthNm);
    // Unpolarised light meets the o and e coefficients in the ratio an isotropic set of fields would: two
    // axes across c to one along it (an approximation, docs/optics.md).
    const double alpha = mixedAbsorption_ ? (2 * o + a.extraordinary(wavelengthNm)) / 3 : o;
    return float(alpha * mmPerUnit_);
}

float TraceBase::rayAbsorption(int axis, float wavelengthNm) const {
    return float(scene_.material().absorption()->ray(axis, wavelengthNm) * mmPerUnit_);
}

float TraceBase::extraordinaryAbsorption(float wavelengthNm) const {
    if (!absorbs_) return 0;
    return float(scene_.material().absorption()->extraordinary(wavelengthNm) * mmPerUnit_);
}

}  // namespace facetlight
