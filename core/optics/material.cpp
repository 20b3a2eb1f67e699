#include "optics/material.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "optics/gem_spectra.h"
#include "util/error.h"
#include "util/excerpt.h"

namespace facetlight {
namespace {

// The published forms of docs/optics.md ("Materials"), L in micrometres.

// n^2 - 1 = sum B_i L^2 / (L^2 - C_i^2), C_i the resonance wavelengths (Malitson's form).
constexpr Dispersion sellmeier(std::array<double, 3> b, std::array<double, 3> c, int terms = 3) {
    Dispersion d{.form = Dispersion::Form::Sellmeier, .b = b, .terms = terms};
    for (int i = 0; i < 3; ++i) d.c2[i] = c[i] * c[i];
    return d;
}

// The same with C_i^2 given (the Schott convention).
constexpr Dispersion sellmeierC2(std::array<double, 3> b, std::array<double, 3> c2) {
    return {.form = Dispersion::Form::Sellmeier, .b = b, .c2 = c2, .terms = 3};
}

// Ghosh (1999): n^2 = A + B L^2 / (L^2 - C) + D L^2 / (L^2 - E).
constexpr Dispersion ghosh(double a, double b, double c, double d, double e) {
    return {.form = Dispersion::Form::Sellmeier, .a = a, .b = {b, d, 0}, .c2 = {c, e, 0}, .terms = 2};
}

// Wang et al. (2013): n^2 = A + B / (L^2 - C) + D L^2 (their D is negative).
constexpr Dispersion wang(double a, double b, double c, double d) {
    return {.form = Dispersion::Form::Sellmeier, .a = a, .b = {b, 0, 0}, .c2 = {c, 0, 0}, .terms = 1,
            .poleOnly = true, .d = d};
}

// Where no fit is published: Cauchy n = A + B / L^2 through the stone's published n at 589.3 nm and its
// published dispersion n(430.8 nm) - n(686.7 nm), the same B for every principal index.
Dispersion cauchy(double nD, double dispersionBG) {
    const auto invL2 = [](double nm) { return 1 / (nm * 1e-3 * nm * 1e-3); };
    const double b = dispersionBG / (invL2(430.8) - invL2(686.7));
    return {.form = Dispersion::Form::Cauchy, .a = nD - b * invL2(Material::kSodiumD), .b = {b, 0, 0}};
}

struct Fit {
    std::string_view name;
    Optic optic;
    std::array<Dispersion, 3> axes;  // as principalIndices() orders them
    double densityGcm3;              // for weights in carats (docs/optics.md, "Materials": the sources)
};

constexpr Fit isotropic(std::string_view name, Dispersion n, double density) {
    return {name, Optic::Isotropic, {n, n, n}, density};
}
constexpr Fit uniaxial(std::string_view name, Dispersion o, Dispersion e, double density) {
    return {name, Optic::Uniaxial, {o, o, e}, density};
}

// Malitson & Dodge (1972), synthetic sapphire; ruby is the same corundum.
constexpr Dispersion kCorundumO = sellmeier({1.4313493, 0.65054713, 5.3414021}, {0.0726631, 0.1193242, 18.028251});
constexpr Dispersion kCorundumE = sellmeier({1.5039759, 0.55069141, 6.5927379}, {0.0740288, 0.1216529, 20.072248});
// Ghosh, Opt. Commun. 163, 95 (1999): alpha quartz; amethyst is the same quartz.
constexpr Dispersion kQuartzO = ghosh(1.28604141, 1.07044083, 1.00585997e-2, 1.10202242, 100);
constexpr Dispersion kQuartzE = ghosh(1.28851804, 1.09509924, 1.02101864e-2, 1.15662475, 100);

// Coefficients and sources as tabulated in docs/optics.md.
const std::vector<Fit>& fits() {
    static const std::vector<Fit> kFits = {
        // Handbook of Optics, 3rd ed., vol. 4 (via refractiveindex.info).
        isotropic("diamond", sellmeier({4.3356, 0.3306, 0}, {0.1060, 0.1750, 0}, 2), 3.52),
        // Wood & Nassau, Appl. Opt. 21, 2978 (1982), 12 mol% Y2O3.
        isotropic("cubic_zirconia",
                  sellmeier({1.347091, 2.117788, 9.452943}, {0.062543, 0.166739, 24.320570}), 5.8),
        uniaxial("sapphire", kCorundumO, kCorundumE, 4.00),
        // Malitson, J. Opt. Soc. Am. 55, 1205 (1965).
        isotropic("fused_silica",
                  sellmeier({0.6961663, 0.4079426, 0.8974794}, {0.0684043, 0.1162414, 9.896161}), 2.20),
        // Schott N-BK7 data sheet; C given squared.
        isotropic(
            "bk7",
            sellmeierC2({1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653}),
            2.51),
        uniaxial("ruby", kCorundumO, kCorundumE, 4.00),
        // Ghosh 1999: alpha quartz (above) and calcite.
        uniaxial("quartz", kQuartzO, kQuartzE, 2.65),
        uniaxial("calcite", ghosh(1.73358749, 0.96464345, 1.94325203e-2, 1.82831454, 120),
                 ghosh(1.35859695, 0.82427830, 1.06689543e-2, 0.14429128, 120), 2.71),
        // Wang et al., Laser Photonics Rev. 7, 831 (2013): 6H-SiC, the moissanite polytype.
        uniaxial("moissanite", wang(6.57232, 0.1401, 0.03178, -0.02153),
                 wang(6.7452, 0.15352, 0.03597, -0.02249), 3.22),
        // Cauchy through the gemmological indices and dispersion (GIA Gem Reference Guide): elbaite
        // tourmaline,
        // high zircon.
        uniaxial("tourmaline", cauchy(1.644, 0.017), cauchy(1.624, 0.017), 3.06),
        uniaxial("zircon", cauchy(1.925, 0.039), cauchy(1.984, 0.039), 4.70),
        // Biaxial: forsterite (Fo100) olivine, Deer, Howie & Zussman (1992); fluorine-rich topaz, Handbook of
        // Mineralogy; each with its gem's dispersion (GIA).
        {"peridot", Optic::Biaxial, {cauchy(1.635, 0.020), cauchy(1.651, 0.020), cauchy(1.670, 0.020)}, 3.22},
        {"topaz", Optic::Biaxial, {cauchy(1.606, 0.014), cauchy(1.609, 0.014), cauchy(1.616, 0.014)}, 3.53},
        // Coloured (spectra: optics/gem_spectra.cpp). Emerald: beryl, Cauchy through GIA's emerald (1.583,
        // 1.577, dispersion 0.014, SG 2.72). Alexandrite: chrysoberyl, Cauchy through the Handbook of
        // Mineralogy's 1.746 / 1.748 / 1.756 and GIA's dispersion 0.015 and SG 3.73.
        uniaxial("blue_sapphire", kCorundumO, kCorundumE, 4.00),
        uniaxial("emerald", cauchy(1.583, 0.014), cauchy(1.577, 0.014), 2.72),
        uniaxial("amethyst", kQuartzO, kQuartzE, 2.65),
        {"alexandrite",
         Optic::Biaxial,
         {cauchy(1.746, 0.015), cauchy(1.748, 0.015), cauchy(1.756, 0.015)},
         3.73},
        // Zoisite (tanzanite): alpha, beta, gamma 1.692, 1.693, 1.700 and SG 3.35 (O'Donoghue, Gems, 6th ed.,
        // 2006); dispersion 0.030, the International Gem Society's (B-G; uncertain: other tables give 0.012).
        {"zoisite", Optic::Biaxial, {cauchy(1.692, 0.030), cauchy(1.693, 0.030), cauchy(1.700, 0.030)}, 3.35},
    };
    return kFits;
}

}  // namespace

Material Material::byName(std::string_view name) {
    for (const Fit& fit : fits()) {
        if (fit.name != name) continue;
        Material m;
        m.name_ = std::string(fit.name);
        m.optic_ = fit.optic;
        m.axes_ = fit.axes;
        m.density_ = fit.densityGcm3;
        m.absorption_ = gemSpectrum(name);
        return m;
    }
    std::string known;
    for (const std::string& n : materialNames()) known += (known.empty() ? "" : ", ") + n;
    // Names the field as the settings readers do, and quotes an excerpt of what was sent.
    throw Error("material must be one of " + known + " (got " + inQuotes(name) + ")");
}

Material Material::constant(double n, std::string name) {
    if (!(n > 1 && n <= 10)) throw Error("n must be greater than 1 and at most 10");
    Material m;
    m.name_ = std::move(name);
    m.axes_.fill({.a = n});
    return m;
}

Material Material::defined(const MaterialDefinition& d) {
    const auto index = [&](double nD) {
        return d.dispersionBG > 0 ? cauchy(nD, d.dispersionBG) : Dispersion{.a = nD};
    };
    Material m;
    m.name_ = d.name;
    if (d.n) {
        m.axes_.fill(index(*d.n));
    } else if (d.nO) {
        m.optic_ = Optic::Uniaxial;
        m.axes_ = {index(*d.nO), index(*d.nO), index(*d.nE)};
    } else {
        m.optic_ = Optic::Biaxial;
        m.axes_ = {index(*d.alpha), index(*d.beta), index(*d.gamma)};
    }
    m.density_ = d.densityGcm3.value_or(0);
    return m;
}

std::array<double, 3> Material::principalIndices(double wavelengthNm) const {
    return {axes_[0].at(wavelengthNm), axes_[1].at(wavelengthNm), axes_[2].at(wavelengthNm)};
}

double Material::birefringence() const {
    const std::array<double, 3> n = principalIndices(kSodiumD);
    return *std::max_element(n.begin(), n.end()) - *std::min_element(n.begin(), n.end());
}

int Material::opticSign() const {
    const std::array<double, 3> n = principalIndices(kSodiumD);
    switch (optic_) {
        case Optic::Isotropic: return 0;
        case Optic::Uniaxial: return n[2] > n[0] ? 1 : -1;
        case Optic::Biaxial: {
            const double twoV = twoVzDegrees();
            return twoV < 90 ? 1 : twoV > 90 ? -1 : 0;
        }
    }
    return 0;
}

double Material::twoVzDegrees() const {
    if (optic_ != Optic::Biaxial) return 0;
    const auto [a, b, g] = principalIndices(kSodiumD);
    const double cos2 = a * a * (g * g - b * b) / (b * b * (g * g - a * a));
    return 2 * std::acos(std::sqrt(cos2)) * 180 / std::numbers::pi;
}

const char* opticName(Optic optic) {
    switch (optic) {
        case Optic::Isotropic: return "isotropic";
        case Optic::Uniaxial: return "uniaxial";
        case Optic::Biaxial: return "biaxial";
    }
    return "isotropic";
}

std::vector<std::string> materialNames() {
    std::vector<std::string> names;
    for (const Fit& fit : fits()) names.emplace_back(fit.name);
    return names;
}

std::vector<std::string> corundumMaterialNames() {
    std::vector<std::string> names;
    for (const Fit& fit : fits())
        if (fit.axes[0] == kCorundumO && fit.axes[2] == kCorundumE) names.emplace_back(fit.name);
    return names;
}

}  // namespace facetlight
