#include "optics/gem_spectra.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace facetlight {
namespace {

// One polarised spectrum as published: decadic absorbance against wavelength through a slab `thicknessMm`.
struct Column {
    double thicknessMm;
    std::vector<double> absorbance;
};

// A sample's columns on one wavelength grid. `ordinary` is averaged over its columns (a biaxial stone's rays,
// docs/optics.md); `extraordinary` is empty or one. `rays`: the ordinary columns are the X, Y and Z rays, in
// that order, and are kept as the trichroic table too.
struct Measured {
    std::string_view material;
    std::vector<double> wavelengthNm;
    std::vector<Column> ordinary;
    std::vector<Column> extraordinary;
    bool rays = false;
};

std::vector<double> grid(double from, double to, double step) {
    std::vector<double> nm;
    for (double x = from; x <= to + 1e-9; x += step) nm.push_back(x);
    return nm;
}

// Every value read from the Caltech Mineral Spectroscopy Server's data files (G. R. Rossman); docs/optics.md,
// "Coloured materials", names each file, its sample and thickness and how the grid was read.
const std::vector<Measured>& measured() {
    static const std::vector<Measured> kMeasured = {
        // Ruby GRR 1843, Chanthaburi, 0.787 mm, E perp c (ru1843.a); no E || c file: e as o.
        {"ruby",
         grid(380, 780, 20),
         {{0.787, {1.093911,  1.624549,  1.752185, 1.072465,  0.5730768, 0.367682,  0.4941079,
                   0.8710999, 1.358882,  1.625175, 1.332955,  0.6835202, 0.343953,  0.2671494,
                   0.2635926, 0.2513637, 0.261001, 0.2457028, 0.2420024, 0.2360097, 0.2316118}}},
         {}},
        // Blue sapphire GRR 1020a, 4.289 mm, E perp c (sa1020a.am) and E || c (sa1020a.cm).
        {"blue_sapphire",
         grid(380, 780, 20),
         {{4.289,
           {1.45816, 0.68340, 0.50517, 0.66245, 0.81248, 0.61594, 0.70691, 0.87966, 1.04427, 1.16510, 1.22449,
            1.23766, 1.24022, 1.25792, 1.30092, 1.37136, 1.46386, 1.58620, 1.73446, 1.90993, 2.09389}}},
         {{4.289,
           {1.39808, 0.77135, 0.64998, 0.73479, 0.84907, 0.61172, 0.57803, 0.57437, 0.56819, 0.57577, 0.60163,
            0.64383, 0.69422, 0.74732, 0.79891, 0.84388, 0.87882, 0.90322, 0.91841, 0.92323, 0.92397}}}},
        // Emerald GRR 3570, Afghanistan, 0.859 mm, E perp c and E || c (Emerald_3570_a.asc, _c.asc).
        {"emerald",
         grid(380, 780, 10),
         {{0.859,
           {0.30147, 0.34543, 0.42765, 0.52195, 0.6167,  0.68125, 0.67573, 0.61882, 0.52133, 0.4091,  0.3174,
            0.23394, 0.19259, 0.18165, 0.18902, 0.209,   0.24252, 0.2919,  0.35552, 0.42919, 0.50485, 0.57225,
            0.61454, 0.61628, 0.57207, 0.50737, 0.48176, 0.3995,  0.34142, 0.29337, 0.27956, 0.2211,  0.18674,
            0.16551, 0.15329, 0.14659, 0.14414, 0.14262, 0.1423,  0.14227, 0.14301}}},
         {{0.859,
           {0.30086, 0.36542, 0.46157, 0.55598, 0.60437, 0.58279, 0.50929, 0.42901, 0.34722, 0.28003, 0.22606,
            0.19207, 0.17772, 0.17955, 0.19525, 0.22208, 0.25918, 0.30646, 0.36315, 0.42286, 0.48087, 0.53905,
            0.61292, 0.68317, 0.76288, 0.82026, 0.82957, 0.86236, 0.74626, 0.63856, 0.52269, 0.48259, 0.35488,
            0.28676, 0.24755, 0.2264,  0.21646, 0.2129,  0.2122,  0.21257, 0.2127}}}},
        // Amethyst, Anahi, Bolivia, 6.17 mm, slab across c (ameth.bo): the o-ray; e as o.
        {"amethyst",
         grid(380, 780, 10),
         {{6.17,
           {0.56533, 0.51539, 0.47895, 0.44319, 0.40189, 0.36179, 0.33543, 0.32675, 0.33189, 0.34552, 0.36516,
            0.38753, 0.40683, 0.42615, 0.43922, 0.44913, 0.45143, 0.4492,  0.44053, 0.42877, 0.41084, 0.39529,
            0.37597, 0.35683, 0.34116, 0.32538, 0.31103, 0.2953,  0.28333, 0.2737,  0.26335, 0.25502, 0.24753,
            0.24957, 0.24287, 0.2328,  0.23834, 0.23727, 0.23501, 0.23531, 0.23853}}},
         {}},
        // Peridot: olivine GRR 418, San Carlos, alpha 1.141 mm, beta 1.1381 mm, gamma 0.66 mm (ol418.a, .b,
        // .g).
        {"peridot",
         grid(380, 780, 20),
         {{1.141,
           {0.24876, 0.21485, 0.14487, 0.11796, 0.10763, 0.07640, 0.05452, 0.03607, 0.01834, 0.01142, 0.01357,
            0.02308, 0.04419, 0.05749, 0.05144, 0.05317, 0.07224, 0.10175, 0.14675, 0.20623, 0.28029}},
          {1.1381,
           {0.32971, 0.27704, 0.20932, 0.20023, 0.19287, 0.14806, 0.12825, 0.07790, 0.05991, 0.04772, 0.05670,
            0.07371, 0.09377, 0.10720, 0.11040, 0.10987, 0.12501, 0.14259, 0.16690, 0.20365, 0.25115}},
          {0.66,
           {0.14832, 0.09694, 0.07293, 0.07741, 0.05958, 0.04553, 0.03250, 0.02032, 0.01572, 0.01264, 0.01534,
            0.01894, 0.02922, 0.03471, 0.03150, 0.03490, 0.04602, 0.06059, 0.08404, 0.11105, 0.14643}}},
         {},
         true},
        // Alexandrite GRR 874, Lake Manyara, 0.717 mm, beta and gamma rays (ch874.a, .b; the server has no
        // alpha); 680 nm left out (the narrow R line, sampled once).
        {"alexandrite",
         [] {
             std::vector<double> nm = grid(380, 780, 10);
             nm.erase(std::find(nm.begin(), nm.end(), 680.0));
             return nm;
         }(),
         {{0.717, {0.68111, 0.95742, 1.39184, 1.76112, 1.92965, 2.01401, 1.78073, 1.22622, 0.75265, 0.50885,
                   0.25605, 0.19517, 0.19451, 0.21826, 0.25929, 0.31353, 0.3728,  0.42464, 0.45421, 0.45112,
                   0.4164,  0.35957, 0.29521, 0.23912, 0.19711, 0.16956, 0.14761, 0.13518, 0.13295, 0.12323,
                   0.11457, 0.11407, 0.11343, 0.11255, 0.11121, 0.11027, 0.11134, 0.11085, 0.11034, 0.11048}},
          {0.717,
           {0.70184, 0.8219,  1.06488, 1.23313, 1.2419,  1.2016,  1.08897, 0.7855,  0.49539, 0.34939,
            0.21382, 0.18754, 0.20486, 0.25109, 0.33475, 0.4662,  0.65328, 0.89452, 1.17461, 1.4625,
            1.70804, 1.86723, 1.89596, 1.78137, 1.60433, 1.25549, 0.85863, 0.6377,  0.44273, 0.29925,
            0.19423, 0.17492, 0.16541, 0.16167, 0.15712, 0.15583, 0.157,   0.15516, 0.15377, 0.15444}}},
         {}},
        // Zoisite GRR 1265 (unheated tanzanite), Tanzania, normalised to 3.00 mm; zo1265.b, .c, .a (E || b,
        // c,
        // a: the X, Y and Z rays), from 410 nm, where the 5 nm copy's every other row begins.
        {"zoisite",
         grid(410, 780, 10),
         {{3.0, {0.22162, 0.20249, 0.19516, 0.20639, 0.21806, 0.22469, 0.22706, 0.23297, 0.24892, 0.26643,
                 0.28674, 0.30784, 0.32139, 0.32699, 0.32642, 0.32214, 0.32159, 0.31947, 0.3096,  0.28983,
                 0.25755, 0.22039, 0.18267, 0.14792, 0.12227, 0.10139, 0.08766, 0.07649, 0.06831, 0.06316,
                 0.06072, 0.05785, 0.05655, 0.05375, 0.05308, 0.05043, 0.04777, 0.04655}},
          {3.0, {0.31732, 0.25773, 0.23316, 0.22476, 0.21425, 0.20447, 0.19627, 0.19453, 0.20111, 0.21393,
                 0.22974, 0.24354, 0.2503,  0.25083, 0.2497,  0.25278, 0.26285, 0.27809, 0.29093, 0.29812,
                 0.2969,  0.28311, 0.26296, 0.24077, 0.22119, 0.21157, 0.20465, 0.20044, 0.21401, 0.22654,
                 0.24029, 0.25463, 0.26626, 0.27757, 0.28512, 0.2868,  0.28352, 0.27509}},
          {3.0, {0.66008, 0.38951, 0.32423, 0.33829, 0.335,   0.30089, 0.24388, 0.19293, 0.16269, 0.1519,
                 0.15245, 0.15825, 0.1621,  0.16685, 0.17244, 0.1805,  0.19298, 0.20896, 0.22252, 0.23233,
                 0.23378, 0.22348, 0.20776, 0.18937, 0.17139, 0.16181, 0.15495, 0.14459, 0.1509,  0.15858,
                 0.1674,  0.17228, 0.17592, 0.17634, 0.17643, 0.17086, 0.16174, 0.15255}}},
         {},
         true},
    };
    return kMeasured;
}

// alpha = ln(10) (A - A_min) / d per mm, averaged over the columns.
std::vector<double> perMm(const std::vector<Column>& columns) {
    std::vector<double> alpha(columns.front().absorbance.size(), 0.0);
    for (const Column& c : columns) {
        const double floor = *std::min_element(c.absorbance.begin(), c.absorbance.end());
        for (size_t i = 0; i < alpha.size(); ++i)
            alpha[i] +=
                std::numbers::ln10 * (c.absorbance[i] - floor) / c.thicknessMm / double(columns.size());
    }
    return alpha;
}

}  // namespace

std::optional<AbsorptionSpectrum> gemSpectrum(std::string_view name) {
    for (const Measured& m : measured()) {
        if (m.material != name) continue;
        AbsorptionSpectrum s{
            .wavelengthNm = m.wavelengthNm,
            .ordinaryPerMm = perMm(m.ordinary),
            .extraordinaryPerMm = m.extraordinary.empty() ? std::vector<double>{} : perMm(m.extraordinary)};
        if (m.rays)
            for (size_t axis = 0; axis < 3; ++axis) s.rayPerMm[axis] = perMm({m.ordinary[axis]});
        return s;
    }
    return std::nullopt;
}

}  // namespace facetlight
