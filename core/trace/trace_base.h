#pragma once
// What the photon tracer prepares from a scene and the trace's settings before its first photon (after
// Tungsten's TraceBase(scene, settings)): the settings go down in one straight line, the scene stays the
// world alone. The statistics trace, the fire trace, the photon pass and the ASET view's rays share it.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "geometry/ray.h"
#include "optics/birefringence.h"
#include "optics/polarization.h"
#include "scene/scene.h"
#include "stats/facet_stats.h"
#include "stats/fire_stats.h"
#include "trace/trace_settings.h"

namespace facetlight {

class TraceBase {
  public:
    // The scene must outlive it; it was made from the same job's scene settings.
    TraceBase(const Scene& scene, const TraceSettings& settings);

    const Scene& scene() const { return scene_; }
    const TraceSettings& settings() const { return settings_; }

    // Collimated light at one index of refraction: every photon entering through facet f meets it at the
    // same angle, so its Fresnel reflectance (in a polarised trace: the share the reflected wave takes of
    // the light's state), both directions and the state inside are worked out once per facet. Empty for
    // other lights and for a dispersive or polarised scene.
    struct FixedEntry {
        float reflectance;
        Vec3f reflected, refracted;
        Polarization inside;  // when polarised
    };
    const std::vector<FixedEntry>& fixedEntries() const { return fixedEntry_; }
    // The same for band k of a fire trace (fireBands(), trace/fire_trace.h), at index bandEntryIndex(k),
    // polarised or not: the packet walk's bands enter by it. Empty without fire, for other lights and in a
    // birefringent stone.
    const std::vector<FixedEntry>& bandEntries(int k) const { return bandEntry_[k]; }
    float bandEntryIndex(int k) const { return bandEntryIndex_[k]; }

    // Whether photons carry their polarisation, and the state a photon leaves the light in along d (stone
    // frame): unpolarised, or linear along the polariser's axis seen across d.
    bool polarized() const { return settings_.polarization == PolarizationMode::On; }
    Polarization sourcePolarization(const Vec3f& d) const {
        return polarizer_ ? Polarization{Stokes{1, 1, 0, 0}, frameAcross(d, *polarizer_)}
                          : Polarization{Stokes{}, frameAcross(d, Vec3f(1, 0, 0))};
    }

    // Whether photons split into two waves: a uniaxial or biaxial material traced with polarisation on
    // (docs/optics.md, "Birefringent stones", "Biaxial crystals"). The crystal at indices n_o, n_e with the
    // job's optic axis; n_e (a biaxial stone's gamma) at a wavelength; and n_e - n_o (gamma - beta) at
    // 589.3 nm, which the fire trace's bands and the view rays add to their n_o (beta) (the birefringence's
    // own dispersion left out there). A biaxial stone's photon carries n = beta, nE = gamma and
    // nA = alpha (alpha - beta at 589.3 nm added to the bands' beta).
    bool birefringent() const { return birefringent_; }
    bool biaxial() const { return biaxial_; }
    UniaxialMedium crystal(float nO, float nE) const { return {nO, nE, opticAxis_}; }
    BiaxialMedium biaxialCrystal(float alpha, float beta, float gamma) const {
        return {alpha, beta, gamma, principalAxes_[0], principalAxes_[1], principalAxes_[2]};
    }
    // The material's principal index 0, 1 or 2 (alpha, beta, gamma; n_o, n_o, n_e) at a wavelength, or at
    // 589.3 nm in a trace without dispersion.
    float principalIndex(int axis, double wavelengthNm) const;
    float birefringenceD() const { return birefringenceD_; }
    float alphaOffsetD() const { return alphaOffsetD_; }
    // Whether a wave normal k is so near the optic axis that the ordinary and extraordinary waves stay within
    // half a wave of each other over the stone's size, (n_e(theta) - n_o) L < lambda / 2 at 550 nm: there
    // light keeps its polarisation as in an isotropic stone at n_o (docs/optics.md, "Birefringent stones").
    // Never for a biaxial stone, whose indices part linearly off its axes (docs/optics.md, "Biaxial
    // crystals").
    bool nearOpticAxis(const Vec3& k) const {
        const double c = dot(k, opticAxis_);
        return birefringent_ && 1 - c * c < coherentSin2_;
    }

    // Absorption (docs/optics.md, "Absorption"): whether the material absorbs at all, and a photon's
    // coefficient per mesh unit at a wavelength (the stone scaled to size_mm): alpha_o for an isotropic
    // material and for the ordinary wave of a birefringent trace, whose extraordinary wave also takes
    // extraordinaryAbsorption(); unpolarised through a uniaxial stone, the mixture 2/3 alpha_o + 1/3 alpha_e.
    bool absorbs() const { return absorbs_; }
    // A biaxial stone traced with polarisation on whose spectrum gives its X, Y and Z rays: each wave absorbs
    // by its field (PhotonWalker::segmentAbsorption), with these per mesh unit at a wavelength.
    bool trichroic() const { return trichroic_; }
    float rayAbsorption(int axis, float wavelengthNm) const;
    const std::array<Vec3, 3>& principalAxes() const { return principalAxes_; }
    float absorption(float wavelengthNm) const;
    float extraordinaryAbsorption(float wavelengthNm) const;
    const Vec3& opticAxis() const { return opticAxis_; }

    // What the tallies need: whether a facet is on the crown side (table or crown), the world's vertical in
    // the stone's frame, the exit-angle bins, cos of the head-shadow half-angle (2 without a head cone) and
    // of each return cone.
    bool crownSide(uint32_t facet) const { return crownSide_[facet]; }
    const Vec3f& up() const { return up_; }
    const ExitAngleBins& exitBin() const { return exitBin_; }
    float cosHeadShadow() const { return cosHeadShadow_; }
    const std::array<float, kConeCount>& cosCone() const { return cosCone_; }

  private:
    const Scene& scene_;
    TraceSettings settings_;
    // PhotonWalker::enter()'s float operations for collimated light at index n, facet by facet.
    std::vector<FixedEntry> fixedEntriesAt(float n) const;

    std::vector<FixedEntry> fixedEntry_;
    std::array<std::vector<FixedEntry>, kFireBands> bandEntry_;
    std::array<float, kFireBands> bandEntryIndex_{};
    std::optional<Vec3f> polarizer_;  // the light's polariser axis, stone frame
    bool birefringent_ = false;
    bool biaxial_ = false;
    Vec3 opticAxis_;
    std::array<Vec3, 3> principalAxes_;
    float alphaOffsetD_ = 0;
    bool absorbs_ = false;
    bool trichroic_ = false;
    bool mixedAbsorption_ = false;  // unpolarised through a uniaxial stone
    double mmPerUnit_ = 1;
    float birefringenceD_ = 0;
    double coherentSin2_ = 0;  // sin^2 of the half-angle of the cone around the axis where the waves stay in phase
    std::vector<uint8_t> crownSide_;  // 1 for table and crown facets
    Vec3f up_;
    ExitAngleBins exitBin_;
    float cosHeadShadow_;
    std::array<float, kConeCount> cosCone_;
};

}  // namespace facetlight
