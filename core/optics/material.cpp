#include "optics/material.h"

#include <cmath>

#include "util/error.h"
#include "util/excerpt.h"

namespace facetlight {
namespace {

struct SellmeierFit {
    std::string_view name;
    std::array<double, 3> b;
    std::array<double, 3> c;  // resonance wavelengths in micrometres (not squared)
    bool cSquared;            // true when `c` already holds C^2 (the Schott convention)
    int terms;
    double densityGcm3;       // for weights in carats (docs/optics.md, "Materials": the sources)
};

// Coefficients as tabulated in docs/optics.md (n^2 - 1 = sum B L^2 / (L^2 - C^2), L in micrometres).
constexpr SellmeierFit kFits[] = {
    // Handbook of Optics, 3rd ed., vol. 4 (via refractiveindex.info).
    {"diamond", {4.3356, 0.3306, 0}, {0.1060, 0.1750, 0}, false, 2, 3.52},
    // Wood & Nassau, Appl. Opt. 21, 2978 (1982), 12 mol% Y2O3.
    {"cubic_zirconia", {1.347091, 2.117788, 9.452943}, {0.062543, 0.166739, 24.320570}, false, 3, 5.8},
    // Malitson, ordinary ray.
    {"sapphire", {1.4313493, 0.65054713, 5.3414021}, {0.0726631, 0.1193242, 18.028251}, false, 3, 4.00},
    // Malitson, J. Opt. Soc. Am. 55, 1205 (1965).
    {"fused_silica", {0.6961663, 0.4079426, 0.8974794}, {0.0684043, 0.1162414, 9.896161}, false, 3, 2.20},
    // Schott N-BK7 data sheet; C given squared.
    {"bk7", {1.03961212, 0.231792344, 1.01046945}, {0.00600069867, 0.0200179144, 103.560653}, true, 3, 2.51},
};

}  // namespace

Material Material::byName(std::string_view name) {
    for (const SellmeierFit& fit : kFits) {
        if (fit.name != name) continue;
        Material m;
        m.name_ = std::string(fit.name);
        m.terms_ = fit.terms;
        m.density_ = fit.densityGcm3;
        m.b_ = fit.b;
        for (int i = 0; i < 3; ++i) m.c2_[i] = fit.cSquared ? fit.c[i] : fit.c[i] * fit.c[i];
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
    m.n0_ = n;
    return m;
}

std::vector<std::string> materialNames() {
    std::vector<std::string> names;
    for (const SellmeierFit& fit : kFits) names.emplace_back(fit.name);
    return names;
}

}  // namespace facetlight
