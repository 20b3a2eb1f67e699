// Corundum by its chromophores (docs/optics.md, "Corundum by its chromophores"): alpha = sigma N against
// GIA's cross sections typed from the data sheet, zero concentrations trace clear, the colours' directions
// and the rays' dichroism, the refusals, and the figures docs/physics.md quotes (printed).
#include "optics/corundum_chromophores.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "colour/cie.h"
#include "colour/colour_space.h"
#include "optics/gem_spectra.h"
#include "optics/material.h"
#include "study/job_request.h"
#include "support/expect_error.h"
#include "support/fixtures.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;

AbsorptionSpectrum corundum(double cr, double feTi) {
    return readAbsorption(json{{"corundum_ppma", {{"cr", cr}, {"fe_ti", feTi}}}}, "absorption");
}

// Atoms per cm^3 in 1 ppma, written out: 5 atoms per Al2O3 of 101.96 g/mol at 4.00 g/cm^3.
constexpr double kPerPpma = 1e-6 * 5 * 6.02214076e23 * 4.00 / 101.96;

// sigma N in 1/mm, sigma in cm^2 as the data sheet gives it (chromium.csv, iron_titanium.csv).
double alphaPerMm(double sigmaCm2, double ppma) {
    return sigmaCm2 * ppma * kPerPpma / 10;
}

TEST(CorundumChromophores, AlphaIsSigmaTimesN) {
    // GIA Box A's 1.178e17 per ppma (at 3.99 g/cm^3, as indicatrix quotes it) against ours at 4.00.
    EXPECT_NEAR(kCorundumAtomsPerCm3 * 1e-6 / 1.178e17, 1.0025, 0.0005);
    // Values from the CSV rows (full precision), the table keeps 4 figures: within 1e-3 relative.
    const struct {
        double nm, cr, feTi;
        CorundumRay ray;
        double sigmaCr, sigmaFeTi;
    } cases[] = {
        {410, 100, 0, CorundumRay::Ordinary, 1.6531543182748426e-19, 3.2403166850196851e-19},
        {398, 100, 0, CorundumRay::Extraordinary, 2.9851665445882467e-19, 3.3911976566699928e-19},
        {560, 250, 0, CorundumRay::Ordinary, 1.6208051780236986e-19, 1.9025689870318646e-18},
        {580, 0, 20, CorundumRay::Ordinary, 1.2207749720495562e-19, 1.980053703919108e-18},
        {700, 0, 20, CorundumRay::Extraordinary, 1.236807926e-21, 1.2540376184480273e-18},
        {694, 1000, 5, CorundumRay::Ordinary, 8.4634857331290707e-21, 1.4471426209527838e-18},
        {480, 40, 30, CorundumRay::Extraordinary, 9.9196743018260401e-21, 5.7353642401176244e-19},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.nm);
        const AbsorptionSpectrum s = corundum(c.cr, c.feTi);
        const double expected = alphaPerMm(c.sigmaCr, c.cr) + alphaPerMm(c.sigmaFeTi, c.feTi);
        const double got = c.ray == CorundumRay::Ordinary ? s.ordinary(c.nm) : s.extraordinary(c.nm);
        EXPECT_NEAR(got / expected, 1, 1e-3);
    }
    // Linear in the concentrations.
    const AbsorptionSpectrum one = corundum(10, 0), two = corundum(20, 0);
    for (double nm : {400.0, 555.0, 693.0}) EXPECT_NEAR(two.ordinary(nm), 2 * one.ordinary(nm), 1e-15);
}

TEST(CorundumChromophores, ItsTableIsAJobsTable) {
    const AbsorptionSpectrum s = corundum(100, 20);
    EXPECT_EQ(s.wavelengthNm.size(), 201u);
    EXPECT_EQ(s.wavelengthNm.front(), 380);
    EXPECT_EQ(s.wavelengthNm.back(), 780);
    // The job's settings keep the concentrations, and read back to the same bits.
    EXPECT_EQ(toJson(s), (json{{"corundum_ppma", {{"cr", 100.0}, {"fe_ti", 20.0}}}}));
    EXPECT_EQ(readAbsorption(toJson(s), "absorption"), s);
    // As a table it passes the reader's checks.
    AbsorptionSpectrum table = s;
    table.corundum.reset();
    EXPECT_EQ(readAbsorption(toJson(table), "absorption"), table);
    EXPECT_EQ(corundumMaterialNames(), (std::vector<std::string>{"sapphire", "ruby", "blue_sapphire"}));
}

TEST(CorundumChromophores, NoChromophoreTracesClear) {
    const AbsorptionSpectrum zero = corundum(0, 0);
    EXPECT_FALSE(zero.absorbs());
    const Stone& stone = test::roundBrilliant();
    for (PolarizationMode polarization : {PolarizationMode::Off, PolarizationMode::On}) {
        TraceSettings s;
        s.photons = 20'000;
        s.threads = 2;
        s.material = "sapphire";
        s.light.model = LightModelKind::Hemisphere;
        s.polarization = polarization;
        const TraceResult clear = test::traceStone(stone, s);
        s.absorption = zero;
        const TraceResult none = test::traceStone(stone, s);
        EXPECT_TRUE(none.stats == clear.stats);
        s.absorption = corundum(100, 0);
        EXPECT_GT(test::traceStone(stone, s).stats.absorbed, 0u);
    }
}

// CIELAB under D65 of what `mm` passes of one ray's alpha, or of the unpolarised mixture 2/3 o + 1/3 e
// (docs/optics.md, "Absorption"), no surface reflection.
enum class Wave { O, E, Mixed };
Lab transmitted(const AbsorptionSpectrum& s, double mm, Wave wave = Wave::Mixed) {
    const auto tau = [&](double nm) {
        const double alpha = wave == Wave::O   ? s.ordinary(nm)
                             : wave == Wave::E ? s.extraordinary(nm)
                                               : (2 * s.ordinary(nm) + s.extraordinary(nm)) / 3;
        return std::exp(-alpha * mm);
    };
    return xyzToLab(tristimulus(Illuminant::D65, tau), whitePoint(Illuminant::D65));
}

TEST(CorundumChromophores, ChromiumIsPinkToRedAndIronTitaniumBlue) {
    for (double cr : {10.0, 100.0, 1000.0}) {
        SCOPED_TRACE(cr);
        const Lab c = transmitted(corundum(cr, 0), 6.5);
        EXPECT_GT(c.a, 0);
        EXPECT_GT(c.a, std::abs(c.b));
    }
    for (double feTi : {10.0, 50.0}) {
        SCOPED_TRACE(feTi);
        const Lab c = transmitted(corundum(0, feTi), 6.5);
        EXPECT_LT(c.b, -5);
        EXPECT_LT(c.b, -std::abs(c.a));
    }
    // More chromium, darker.
    EXPECT_LT(transmitted(corundum(1000, 0), 6.5).L, transmitted(corundum(100, 0), 6.5).L - 10);
    EXPECT_LT(transmitted(corundum(100, 0), 6.5).L, transmitted(corundum(10, 0), 6.5).L);
}

// Corundum's Cr3+ is dichroic: the e ray's band peaks near 400 nm, above the o ray's there, and the o ray
// absorbs the more at the 560 nm band (GIA: the Y band's e ray, the U band's o ray).
TEST(CorundumChromophores, TheRaysDiffer) {
    const AbsorptionSpectrum s = corundum(100, 0);
    double peakNm = 0, peak = 0;
    for (double nm = 380; nm <= 450; nm += 2) {
        if (s.extraordinary(nm) > peak) {
            peak = s.extraordinary(nm);
            peakNm = nm;
        }
    }
    EXPECT_NEAR(peakNm, 398, 4);
    EXPECT_GT(s.extraordinary(400), 1.5 * s.ordinary(400));
    EXPECT_GT(s.ordinary(560), 2.5 * s.extraordinary(560));
    // Seen through 6.5 mm: the o ray purplish red, the e ray orange-red (b* above the o ray's).
    EXPECT_GT(transmitted(s, 6.5, Wave::E).b, transmitted(s, 6.5, Wave::O).b + 10);
}

std::string errorField(const json& job) {
    return test::refusedField([&] { JobRequest::fromJson(job); });
}

json job(const json& material, const json& absorption) {
    json j = {{"mesh", "round_brilliant"}, {"absorption", absorption}};
    j.update(material);
    return j;
}

TEST(CorundumChromophores, RefusalsNameTheField) {
    const json ppma = {{"corundum_ppma", {{"cr", 100}}}};
    for (const char* m : {"ruby", "sapphire", "blue_sapphire"})
        EXPECT_EQ(errorField(job({{"material", m}}, ppma)), "no error") << m;
    for (const json& m : {json{{"material", "diamond"}}, json{{"material", "emerald"}},
                          json{{"material", "auto"}}, json::object(), json{{"n", 1.77}},
                          json{{"custom_material", {{"name", "c"}, {"n_o", 1.768}, {"n_e", 1.760}}}}})
        EXPECT_EQ(errorField(job(m, ppma)), "absorption.corundum_ppma") << m;
    const json ruby = {{"material", "ruby"}};
    for (const json& bad : {json(-1), json(10001), json("100"), json(nullptr)})
        EXPECT_EQ(errorField(job(ruby, {{"corundum_ppma", {{"cr", bad}}}})), "absorption.corundum_ppma.cr")
            << bad;
    EXPECT_EQ(errorField(job(ruby, {{"corundum_ppma", {{"fe_ti", -0.5}}}})),
              "absorption.corundum_ppma.fe_ti");
    EXPECT_EQ(errorField(job(ruby, {{"corundum_ppma", {{"v", 10}}}})), "absorption.corundum_ppma.v");
    EXPECT_EQ(errorField(job(ruby, {{"corundum_ppma", json::object()}})), "absorption.corundum_ppma");
    EXPECT_EQ(errorField(job(ruby, {{"corundum_ppma", 100}})), "absorption.corundum_ppma");
    json withTable = ppma;
    withTable["wavelength_nm"] = {400, 700};
    withTable["ordinary_per_mm"] = {0.1, 0.2};
    EXPECT_EQ(errorField(job(ruby, withTable)), "absorption.ordinary_per_mm");
    json withColour = ppma;
    withColour["transmitted_colour"] = "#5b8fd0";
    EXPECT_EQ(errorField(job(ruby, withColour)), "absorption.transmitted_colour");
}

// The figures of docs/physics.md, "Corundum by its chromophores, checked" (run this test with
// --gtest_filter='*Figures*' to see them), and the checks they rest on.
TEST(CorundumChromophores, FiguresForThePhysicsNotes) {
    // GIA's cross sections carry natural-log coefficients: GIA's Appendix 2 colours of Cr3+'s rays under D65
    // (as indicatrix's gia_cr3plus_sample1110_sigma.csv copies them: ray, ppma cm, L* a* b*) follow from
    // T = exp(-sigma N L), not from 10^(-sigma N L). (Its unpolarised rows, "(2 E_perp + E_par) / 3", match
    // neither the mixture of alphas nor of transmissions as well: their rule is not known here.)
    const struct {
        Wave wave;
        double ppmaCm;
        Lab gia;
    } appendix2[] = {{Wave::O, 100, {70.46, 37.74, -23.77}},
                     {Wave::E, 100, {87.94, 12.45, 7.64}},
                     {Wave::O, 750, {33.33, 69.94, -18.47}},
                     {Wave::E, 750, {52.09, 67.15, 11.41}}};
    for (const auto& row : appendix2) {
        const AbsorptionSpectrum s = corundum(row.ppmaCm, 0);  // through 1 cm
        AbsorptionSpectrum decadic = s;
        for (std::vector<double>* column : {&decadic.ordinaryPerMm, &decadic.extraordinaryPerMm})
            for (double& a : *column) a *= std::log(10.0);
        const Lab natural = transmitted(s, 10, row.wave), base10 = transmitted(decadic, 10, row.wave);
        const char* ray = row.wave == Wave::O ? "o" : "e";
        std::printf(
            "GIA App. 2, Cr3+ %s, %.0f ppma cm, D65: %.2f %.2f %.2f; exp: %.2f %.2f %.2f (dE %.1f); "
            "10^: %.2f %.2f %.2f (dE %.1f)\n",
            ray, row.ppmaCm, row.gia.L, row.gia.a, row.gia.b, natural.L, natural.a, natural.b,
            deltaE(natural, row.gia), base10.L, base10.a, base10.b, deltaE(base10, row.gia));
        EXPECT_LT(deltaE(natural, row.gia), 4) << ray << " " << row.ppmaCm;
        EXPECT_GT(deltaE(base10, row.gia), 20) << ray << " " << row.ppmaCm;
    }

    // The shipped Caltech ruby's ordinary spectrum against GIA's Cr3+ o ray: N by least squares over
    // 400-650 nm, alpha_caltech = N sigma.
    const AbsorptionSpectrum caltech = *gemSpectrum("ruby");
    const AbsorptionSpectrum unit = corundum(1, 0);
    double sa = 0, ss = 0, aa = 0, peak = 0;
    int points = 0;
    for (size_t i = 0; i < caltech.wavelengthNm.size(); ++i) {
        const double nm = caltech.wavelengthNm[i];
        if (nm < 400 || nm > 650) continue;
        const double a = caltech.ordinaryPerMm[i], s = unit.ordinary(nm);
        sa += s * a;
        ss += s * s;
        aa += a * a;
        peak = std::max(peak, a);
        ++points;
    }
    const double ppma = sa / ss;
    std::printf("Caltech ruby less GIA Cr3+ at the fitted N, 1/mm:");
    for (size_t i = 0; i < caltech.wavelengthNm.size(); ++i) {
        const double nm = caltech.wavelengthNm[i];
        if (nm >= 400 && nm <= 650)
            std::printf(" %.0f %+.2f", nm, caltech.ordinaryPerMm[i] - ppma * unit.ordinary(nm));
    }
    std::printf("\n");
    const double rms = std::sqrt((aa - sa * sa / ss) / points);
    std::printf(
        "Caltech ruby GRR 1843 o ray vs GIA Cr3+ o, 400-650 nm (%d points): %.0f ppma Cr, rms residual "
        "%.3f /mm (%.1f %% of its peak %.3f /mm)\n",
        points, ppma, rms, 100 * rms / peak, peak);
    EXPECT_GT(ppma, 500);
    EXPECT_LT(ppma, 10000);
    EXPECT_LT(rms, 0.15 * peak);

    std::printf("corundum, D65, L* a* b*: unpolarised (2o + e)/3 | o ray | e ray\n");
    const struct { double cr, feTi; } stones[] = {{10, 0}, {100, 0}, {1000, 0}, {0, 10}, {0, 50}};
    for (const auto& st : stones) {
        const AbsorptionSpectrum s = corundum(st.cr, st.feTi);
        for (double mm : {1.0, 6.5}) {
            const Lab m = transmitted(s, mm), o = transmitted(s, mm, Wave::O),
                      e = transmitted(s, mm, Wave::E);
            std::printf(
                "  cr %6.0f fe_ti %3.0f ppma, %3.1f mm: %5.1f %6.1f %6.1f | %5.1f %6.1f %6.1f | %5.1f %6.1f "
                "%6.1f\n",
                st.cr, st.feTi, mm, m.L, m.a, m.b, o.L, o.a, o.b, e.L, e.a, e.b);
        }
    }
}

}  // namespace
}  // namespace facetlight
