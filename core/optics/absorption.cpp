#include "optics/absorption.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
    if (at <= x.front()) return y.front();
    if (at >= x.back()) return y.back();
    const size_t i = size_t(std::upper_bound(x.begin(), x.end(), at) - x.begin());
    const double f = (at - x[i - 1]) / (x[i] - x[i - 1]);
    return y[i - 1] + (y[i] - y[i - 1]) * f;
}

std::string at(const std::string& path, size_t i) {
    return path + "[" + std::to_string(i) + "]";
}

// An array of kMinPoints to kMaxPoints finite numbers in [lo, hi], `count` of them when count > 0.
std::vector<double> readColumn(const json& j, const std::string& path, double lo, double hi, size_t count,
                               const char* what) {
    if (!j.is_array()) throw Error(path, path + " must be an array of " + what);
    if (count > 0 && j.size() != count)
        throw Error(path, path + " must have one value per wavelength (" + std::to_string(count) + ", got " +
                              std::to_string(j.size()) + ")");
    if (j.size() < AbsorptionSpectrum::kMinPoints || j.size() > AbsorptionSpectrum::kMaxPoints)
        throw Error(path, path + " must have " + std::to_string(AbsorptionSpectrum::kMinPoints) + " to " +
                              std::to_string(AbsorptionSpectrum::kMaxPoints) + " points (got " +
                              std::to_string(j.size()) + ")");
    std::vector<double> v;
    for (size_t i = 0; i < j.size(); ++i) {
        const json& x = j[i];
        if (!x.is_number() || !std::isfinite(x.get<double>()) || x.get<double>() < lo ||
            x.get<double>() > hi) {
            std::ostringstream range;
            range << lo << " to " << hi;
            throw Error(at(path, i), at(path, i) + " must be a number from " + range.str());
        }
        v.push_back(x.get<double>());
    }
    return v;
}

}  // namespace

double AbsorptionSpectrum::ordinary(double nm) const {
    return interpolate(wavelengthNm, ordinaryPerMm, nm);
}

double AbsorptionSpectrum::extraordinary(double nm) const {
    return extraordinaryPerMm.empty() ? ordinary(nm) : interpolate(wavelengthNm, extraordinaryPerMm, nm);
}

bool AbsorptionSpectrum::absorbs() const {
    const auto positive = [](double a) { return a > 0; };
    return std::any_of(ordinaryPerMm.begin(), ordinaryPerMm.end(), positive) ||
           std::any_of(extraordinaryPerMm.begin(), extraordinaryPerMm.end(), positive);
}

AbsorptionSpectrum readAbsorption(const json& j, const std::string& path) {
    if (!j.is_object())
        throw Error(path, path + " must be an object {\"wavelength_nm\": [...], \"ordinary_per_mm\": [...]}");
    for (const auto& [key, value] : j.items()) {
        if (key != "wavelength_nm" && key != "ordinary_per_mm" && key != "extraordinary_per_mm")
            throw Error(path + "." + key, "unknown field '" + path + "." + key +
                                              "' (a spectrum has wavelength_nm, ordinary_per_mm and "
                                              "extraordinary_per_mm)");
    }
    for (const char* key : {"wavelength_nm", "ordinary_per_mm"}) {
        if (!j.contains(key)) throw Error(path + "." + key, path + "." + key + " is missing");
    }
    AbsorptionSpectrum s;
    const std::string wl = path + ".wavelength_nm";
    s.wavelengthNm = readColumn(j["wavelength_nm"], wl, AbsorptionSpectrum::kMinNm,
                                AbsorptionSpectrum::kMaxNm, 0, "wavelengths in nm");
    for (size_t i = 1; i < s.wavelengthNm.size(); ++i) {
        if (!(s.wavelengthNm[i] > s.wavelengthNm[i - 1]))
            throw Error(at(wl, i), at(wl, i) + " must be above " + at(wl, i - 1) +
                                       ": wavelengths must be strictly increasing");
    }
    const size_t n = s.wavelengthNm.size();
    s.ordinaryPerMm = readColumn(j["ordinary_per_mm"], path + ".ordinary_per_mm", 0,
                                 AbsorptionSpectrum::kMaxPerMm, n, "coefficients per mm");
    if (j.contains("extraordinary_per_mm"))
        s.extraordinaryPerMm = readColumn(j["extraordinary_per_mm"], path + ".extraordinary_per_mm", 0,
                                          AbsorptionSpectrum::kMaxPerMm, n, "coefficients per mm");
    return s;
}

json toJson(const AbsorptionSpectrum& s) {
    json j = {{"wavelength_nm", s.wavelengthNm}, {"ordinary_per_mm", s.ordinaryPerMm}};
    if (!s.extraordinaryPerMm.empty()) j["extraordinary_per_mm"] = s.extraordinaryPerMm;
    return j;
}

}  // namespace facetlight
