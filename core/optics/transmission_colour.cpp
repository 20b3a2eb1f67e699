#include "optics/transmission_colour.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <string>

#include "colour/cie.h"
#include "util/error.h"

namespace facetlight {
namespace {

using Coefficients = std::array<double, 3>;

// Jakob & Hanika (2019), eq. 3: a sigmoid that reaches 0 and 1 only at infinity, so T stays a transmittance.
double sigmoid(double z) {
    return 0.5 + z / (2 * std::sqrt(1 + z * z));
}

// T at `nm` for coefficients c of the quadratic in t = (nm - 580) / 200, which spans -1 to 1 over 380-780 nm
// (scaled, so that the three coefficients are of one size for the fit).
double transmittance(const Coefficients& c, double nm) {
    const double t = (nm - 580) / 200;
    return sigmoid(c[0] + c[1] * t + c[2] * t * t);
}

Lab labOf(const Coefficients& c) {
    const Vec3 xyz = tristimulus(Illuminant::D65, [&](double nm) { return transmittance(c, nm); });
    return xyzToLab(xyz, whitePoint(Illuminant::D65));
}

std::array<double, 3> minus(const Lab& a, const Lab& b) {
    return {a.L - b.L, a.a - b.a, a.b - b.b};
}

// Levenberg-Marquardt from `c` toward `target`, the Jacobian by central differences; returns Delta E*ab.
// Its constants are the usual ones (Press et al., Numerical Recipes 3rd ed., 15.5.2: damping from 1e-3, cut
// by a factor on success and raised by a larger one on failure); Delta E 1e-4 is far below what an eye or the
// tracer's noise resolves; a step of 1e-5 in coefficients of order 1 to 10 keeps the central difference's
// rounding (1e-16 / 1e-5) and truncation (1e-10) errors far below the fit's tolerance.
double fit(Coefficients& c, const Lab& target) {
    constexpr double kStep = 1e-5;
    double lambda = 1e-3, error = deltaE(labOf(c), target);
    for (int iteration = 0; iteration < 200 && error > 1e-4; ++iteration) {
        const std::array<double, 3> r = minus(labOf(c), target);
        double jac[3][3];  // d Lab_i / d c_k
        for (int k = 0; k < 3; ++k) {
            Coefficients up = c, down = c;
            up[k] += kStep;
            down[k] -= kStep;
            const std::array<double, 3> d = minus(labOf(up), labOf(down));
            for (int i = 0; i < 3; ++i) jac[i][k] = d[i] / (2 * kStep);
        }
        // (J^T J + lambda diag(J^T J)) step = -J^T r, by Cramer's rule (3 x 3).
        double a[3][3], g[3];
        for (int k = 0; k < 3; ++k) {
            g[k] = 0;
            for (int i = 0; i < 3; ++i) g[k] -= jac[i][k] * r[i];
            for (int l = 0; l < 3; ++l) {
                a[k][l] = 0;
                for (int i = 0; i < 3; ++i) a[k][l] += jac[i][k] * jac[i][l];
            }
        }
        for (int k = 0; k < 3; ++k) a[k][k] *= 1 + lambda;
        const auto det = [](const double m[3][3]) {
            return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                   m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                   m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        };
        const double d = det(a);
        if (!(std::abs(d) > 0)) break;
        Coefficients next = c;
        for (int k = 0; k < 3; ++k) {
            double m[3][3];
            for (int i = 0; i < 3; ++i)
                for (int l = 0; l < 3; ++l) m[i][l] = l == k ? g[i] : a[i][l];
            next[k] += det(m) / d;
        }
        const double nextError = deltaE(labOf(next), target);
        if (nextError < error) {
            c = next;
            error = nextError;
            lambda = std::max(lambda / 4, 1e-9);
        } else {
            lambda *= 8;
            if (lambda > 1e9) break;
        }
    }
    return error;
}

}  // namespace

const std::vector<double> kTransmissionWavelengthsNm = [] {
    std::vector<double> nm;
    for (int w = 380; w <= 780; w += 10) nm.push_back(w);
    return nm;
}();

std::vector<double> absorptionForTransmittedColour(const Lab& target, double pathMm,
                                                   const std::string& field) {
    // From the neutral grey of the target's lightness toward the target in steps (continuation, as Jakob &
    // Hanika build their tables), so that each fit starts near its answer (eight steps: each a
    // small move in CIELAB).
    Coefficients c{0, 0, 0};
    const double greyL = labOf(c).L;
    constexpr int kSteps = 8;
    double error = 0;
    for (int step = 1; step <= kSteps; ++step) {
        const double f = double(step) / kSteps;
        const Lab towards{greyL + (target.L - greyL) * f, target.a * f, target.b * f};
        error = fit(c, towards);
    }
    // A colour the smooth spectra can transmit is reached to about 1e-4; one left 0.05 away (far below the
    // just-noticeable Delta E of about 2.3, Sharma, Digital Color Imaging Handbook, 2003) lies outside them.
    if (error > 0.05) {
        char text[160];
        std::snprintf(text, sizeof text,
                      " L* %.1f a* %.1f b* %.1f is no colour a filter transmits (the nearest smooth spectrum "
                      "is Delta E %.1f away)",
                      target.L, target.a, target.b, error);
        throw Error(field, field + text);
    }
    std::vector<double> alpha;
    for (const double nm : kTransmissionWavelengthsNm)
        alpha.push_back(std::max(0.0, -std::log(transmittance(c, nm)) / pathMm));
    return alpha;
}

Lab srgbHexToLab(const std::string& hex, const std::string& field) {
    unsigned r = 0, g = 0, b = 0;
    int used = 0;
    const bool digits =
        hex.size() == 7 && hex[0] == '#' &&
        std::all_of(hex.begin() + 1, hex.end(), [](unsigned char c) { return std::isxdigit(c); });
    if (!digits || std::sscanf(hex.c_str(), "#%2x%2x%2x%n", &r, &g, &b, &used) != 3 || used != 7)
        throw Error(field, field + " must be an sRGB colour \"#rrggbb\" or CIELAB [L*, a*, b*]");
    const Vec3 rgb{srgbDecode(r / 255.0), srgbDecode(g / 255.0), srgbDecode(b / 255.0)};
    return xyzToLab(linearSrgbToXyz(rgb), linearSrgbToXyz({1, 1, 1}));
}

}  // namespace facetlight
