#include "optics/polarization.h"

#include <gtest/gtest.h>

#include <cmath>

#include "optics/fresnel.h"

using namespace facetlight;

namespace {

// Fresnel's reflectances for s and p light from index n1 into n2 at incidence theta (Born & Wolf, Principles
// of Optics, 7th ed., eq. 1.5.(20)-(21)), in double and from the angles themselves.
struct Reflectances {
    double s, p;
};
Reflectances fresnelExact(double theta, double n1, double n2) {
    const double thetaT = std::asin(n1 / n2 * std::sin(theta));
    const double rs = -std::sin(theta - thetaT) / std::sin(theta + thetaT);
    const double rp = std::tan(theta - thetaT) / std::tan(theta + thetaT);
    return {rs * rs, rp * rp};
}

float cosOf(double deg) {
    return float(std::cos(radians(deg)));
}

}  // namespace

TEST(Polarization, FresnelSAndPAgainstTheFormulas) {
    struct Interface {
        double n1, n2;
    };
    for (const Interface& i :
         {Interface{1, 1.5}, Interface{1, 2.4173}, Interface{2.4173, 1}, Interface{1.5, 1}}) {
        const double critical = i.n1 > i.n2 ? degrees(std::asin(i.n2 / i.n1)) : 90;
        for (double deg = 1; deg < std::min(critical, 89.0); deg += 4) {
            const FacetWaves w = facetWaves(cosOf(deg), float(i.n1 / i.n2));
            ASSERT_FALSE(w.totalInternal) << deg;
            const Reflectances exact = fresnelExact(radians(deg), i.n1, i.n2);
            // s light is S1 = 1 in the facet's frame, p light S1 = -1.
            EXPECT_NEAR(w.reflected.share({1, 1, 0, 0}), exact.s, 3e-6)
                << i.n1 << " to " << i.n2 << " at " << deg;
            EXPECT_NEAR(w.reflected.share({1, -1, 0, 0}), exact.p, 3e-6)
                << i.n1 << " to " << i.n2 << " at " << deg;
            // Unpolarised light reflects the average, the tracer's unpolarised Fresnel term.
            EXPECT_NEAR(w.reflected.share({}), fresnel(cosOf(deg), float(i.n1 / i.n2)).reflectance, 1e-6);
            // Energy: what is not reflected is refracted, for any state.
            for (const Stokes& s :
                 {Stokes{}, Stokes{1, 1, 0, 0}, Stokes{1, -0.6f, 0.8f, 0}, Stokes{1, 0, 0, 1}})
                EXPECT_NEAR(w.reflected.share(s) + w.refracted.share(s), 1.0, 1e-6);
            // Snell's law.
            EXPECT_NEAR(std::acos(w.cosT), std::asin(i.n1 / i.n2 * std::sin(radians(deg))), 1e-3);
        }
    }
}

TEST(Polarization, BrewsterAngleReflectsNoPLight) {
    for (double n : {1.5, 2.4173}) {
        // From outside at atan(n) and from inside at atan(1 / n) (Born & Wolf, sec. 1.5.3).
        for (const auto& [deg, eta] :
             {std::pair{degrees(std::atan(n)), 1 / n}, std::pair{degrees(std::atan(1 / n)), n}}) {
            const FacetWaves w = facetWaves(cosOf(deg), float(eta));
            EXPECT_LT(w.reflected.share({1, -1, 0, 0}), 1e-6) << n << " at " << deg;
            EXPECT_GT(w.reflected.share({1, 1, 0, 0}), 0.1) << n << " at " << deg;
            // Unpolarised light reflects fully polarised across the plane of incidence.
            const Stokes r = w.reflected.apply({});
            EXPECT_NEAR(r.s1, 1.0, 1e-5);
            EXPECT_NEAR(r.degree(), 1.0, 1e-5);
            // One degree off, p light reflects again.
            EXPECT_GT(facetWaves(cosOf(deg + 1), float(eta)).reflected.share({1, -1, 0, 0}), 1e-5);
        }
    }
}

TEST(Polarization, TotalInternalReflectionRetardsPAgainstS) {
    // Born & Wolf eq. 1.5.(60): tan(delta / 2) = cos(theta) sqrt(sin^2 theta - n^2) / sin^2 theta, n = n2 /
    // n1.
    const double n1 = 1.51, n = 1 / n1;
    for (double deg = 42; deg < 89; deg += 3) {
        const FacetWaves w = facetWaves(cosOf(deg), float(n1));
        ASSERT_TRUE(w.totalInternal);
        const double t = radians(deg);
        const double expected = 2 * std::atan(std::cos(t) * std::sqrt(std::sin(t) * std::sin(t) - n * n) /
                                              (std::sin(t) * std::sin(t)));
        EXPECT_NEAR(std::abs(std::atan2(w.reflected.e, w.reflected.c)), expected, 2e-5) << deg;
        EXPECT_NEAR(w.reflected.share({1, 0.3f, -0.5f, 0.2f}), 1.0, 1e-6) << "all is reflected";
    }
    // Fresnel's rhomb: two reflections at 54.6 deg in glass of 1.51 turn light polarised at 45 deg to the
    // plane of incidence into circular light (Born & Wolf, sec. 1.5.4; Hecht, Optics, sec. 8.6).
    const FacetWaves rhomb = facetWaves(cosOf(54.6), 1.51f);
    const Stokes once = rhomb.reflected.apply(Stokes::linear(radians(45)));
    const Stokes twice = rhomb.reflected.apply(once);
    EXPECT_NEAR(std::abs(once.s3), std::sin(radians(45)), 2e-3) << "an eighth wave each";
    EXPECT_NEAR(std::abs(twice.s3), 1.0, 1e-4);
    EXPECT_NEAR(twice.degree(), 1.0, 1e-5);
    // Light polarised along s or p stays linear.
    EXPECT_NEAR(rhomb.reflected.apply(rhomb.reflected.apply({1, 1, 0, 0})).s1, 1.0, 1e-6);
}

TEST(Polarization, MalusLawThroughAnAnalyser) {
    const Vec3f d(0, 0, 1), x(1, 0, 0);
    for (double psi = 0; psi < 180; psi += 15) {
        const Polarization light{Stokes::linear(radians(psi)), x};
        for (double theta = 0; theta < 180; theta += 20) {
            const Vec3f axis(float(std::cos(radians(theta))), float(std::sin(radians(theta))), 0);
            const double c = std::cos(radians(psi - theta));
            EXPECT_NEAR(analyserShare(light, d, axis), c * c, 1e-6) << psi << " through " << theta;
        }
    }
    EXPECT_NEAR(analyserShare({Stokes{}, x}, d, Vec3f(0.6f, 0.8f, 0)), 0.5, 1e-7);
    // Circular light passes half of any analyser.
    EXPECT_NEAR(analyserShare({Stokes{1, 0, 0, 1}, x}, d, Vec3f(0.6f, 0.8f, 0)), 0.5, 1e-7);
}

TEST(Polarization, TurningTheFrameKeepsTheLight) {
    const Vec3f d = normalize(Vec3f(0.2f, -0.3f, 0.9f));
    const Vec3f x = frameAcross(d, Vec3f(1, 0, 0));
    EXPECT_NEAR(dot(x, d), 0.0, 1e-6);
    const Vec3f y = cross(d, x);
    const Stokes s{1, 0.3f, -0.4f, 0.5f};
    // Turned by 90 deg: x and y swap, so S1 and S2 change sign; S3 and the degree stay.
    const Stokes r = rotateFrame(s, x, y, d);
    EXPECT_NEAR(r.s1, -0.3, 1e-6);
    EXPECT_NEAR(r.s2, 0.4, 1e-6);
    EXPECT_EQ(r.s3, s.s3);
    // Linear light at 30 deg from x is at 30 - 50 deg from a frame turned by 50 deg.
    const Vec3f turned = x * float(std::cos(radians(50))) + y * float(std::sin(radians(50)));
    const Stokes l = rotateFrame(Stokes::linear(radians(30)), x, turned, d);
    EXPECT_NEAR(l.s1, std::cos(radians(-40)), 1e-6);
    EXPECT_NEAR(l.s2, std::sin(radians(-40)), 1e-6);
    EXPECT_NEAR(std::hypot(l.s1, l.s2), 1.0, 1e-6);
}
