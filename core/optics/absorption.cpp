#include "optics/absorption.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "optics/transmission_colour.h"
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

// A colour by transmission: "#rrggbb" or [L*, a*, b*] (docs/optics.md, "Colour by transmission").
Lab readColour(const json& j, const std::string& path) {
    const bool lab = j.is_array() && j.size() == 3 &&
                     std::all_of(j.begin(), j.end(), [](const json& x) { return x.is_number(); });
    if (!j.is_string() && !lab)
        throw Error(path, path + " must be an sRGB colour \"#rrggbb\" or CIELAB [L*, a*, b*]");
    const Lab c = j.is_string() ? srgbHexToLab(j.get<std::string>(), path)
                                : Lab{j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
    if (!(c.L > 0 && c.L <= 100) || !(std::abs(c.a) <= 200) || !(std::abs(c.b) <= 200))
        throw Error(path, path + " must have L* above 0 and at most 100, a* and b* from -200 to 200");
    return c;
}

// {"transmitted_colour": ..., "extraordinary_transmitted_colour": ..., "path_mm": ...}: the spectra that
// transmit those colours through path_mm (default 1 mm).
AbsorptionSpectrum readTransmittedColour(const json& j, const std::string& path) {
    double pathMm = 1;
    if (j.contains("path_mm")) {
        const json& p = j["path_mm"];
        if (!p.is_number() || !(p.get<double>() >= 0.01 && p.get<double>() <= 1000))
            throw Error(path + ".path_mm", path + ".path_mm must be a number from 0.01 to 1000 (mm)");
        pathMm = p.get<double>();
    }
    AbsorptionSpectrum s;
    s.wavelengthNm = kTransmissionWavelengthsNm;
    const std::string o = path + ".transmitted_colour";
    s.ordinaryPerMm = absorptionForTransmittedColour(readColour(j["transmitted_colour"], o), pathMm, o);
    if (j.contains("extraordinary_transmitted_colour")) {
        const std::string e = path + ".extraordinary_transmitted_colour";
        s.extraordinaryPerMm =
            absorptionForTransmittedColour(readColour(j["extraordinary_transmitted_colour"], e), pathMm, e);
    }
    return s;
}

// {"corundum_ppma": {"cr": ..., "fe_ti": ...}}: the o and e spectra of corundum holding those chromophores
// (docs/optics.md, "Corundum by its chromophores"). The whole table: nothing else may come with it.
AbsorptionSpectrum readCorundum(const json& j, const std::string& path) {
    for (const auto& [key, value] : j.items()) {
        if (key != "corundum_ppma")
            throw Error(path + "." + key, path + "." + key + " cannot go with " + path +
                                              ".corundum_ppma, which makes the whole spectrum from the "
                                              "concentrations: give one or the other");
    }
    const std::string at = path + ".corundum_ppma";
    const json& c = j["corundum_ppma"];
    if (!c.is_object() || c.empty())
        throw Error(at, at + " must be an object of concentrations in ppma, {\"cr\": ..., \"fe_ti\": ...}");
    CorundumChromophores ppma;
    for (const auto& [key, value] : c.items()) {
        const std::string field = at + "." + key;
        double* into = key == "cr" ? &ppma.crPpma : key == "fe_ti" ? &ppma.feTiPpma : nullptr;
        if (!into)
            throw Error(field, "unknown field '" + field +
                                   "' (the chromophores are cr, Cr3+, and fe_ti, Fe2+-Ti4+ pairs, in ppma)");
        if (!value.is_number() ||
            !(value.get<double>() >= 0 && value.get<double>() <= CorundumChromophores::kMaxPpma))
            throw Error(field,
                        field + " must be a number from 0 to 10000 (ppma: parts per million of all atoms)");
        *into = value.get<double>();
    }
    return {.wavelengthNm = corundumWavelengthsNm(),
            .ordinaryPerMm = corundumAbsorptionPerMm(ppma, CorundumRay::Ordinary),
            .extraordinaryPerMm = corundumAbsorptionPerMm(ppma, CorundumRay::Extraordinary),
            .corundum = ppma};
}

}  // namespace

double AbsorptionSpectrum::ordinary(double nm) const {
    return interpolate(wavelengthNm, ordinaryPerMm, nm);
}

double AbsorptionSpectrum::extraordinary(double nm) const {
    return extraordinaryPerMm.empty() ? ordinary(nm) : interpolate(wavelengthNm, extraordinaryPerMm, nm);
}

double AbsorptionSpectrum::ray(int axis, double nm) const {
    return interpolate(wavelengthNm, rayPerMm[size_t(axis)], nm);
}

std::vector<double> AbsorptionSpectrum::meanOfRays(const std::array<std::vector<double>, 3>& rays) {
    std::vector<double> mean(rays[0].size(), 0.0);
    for (const std::vector<double>& r : rays)
        for (size_t i = 0; i < mean.size(); ++i) mean[i] += r[i] / 3.0;
    return mean;
}

bool AbsorptionSpectrum::absorbs() const {
    // The rays' mean is ordinaryPerMm: positive where any ray is.
    const auto positive = [](double a) { return a > 0; };
    return std::any_of(ordinaryPerMm.begin(), ordinaryPerMm.end(), positive) ||
           std::any_of(extraordinaryPerMm.begin(), extraordinaryPerMm.end(), positive);
}

AbsorptionSpectrum readAbsorption(const json& j, const std::string& path) {
    if (!j.is_object())
        throw Error(path, path + " must be an object {\"wavelength_nm\": [...], \"ordinary_per_mm\": [...]}");
    if (j.contains("corundum_ppma")) return readCorundum(j, path);
    // Three more forms: a table of o (and e) columns, a biaxial material's table of rays, or a colour by
    // transmission; transmitted_colour's or x_per_mm's presence decides.
    const bool byColour = j.contains("transmitted_colour");
    const bool byRays =
        !byColour && (j.contains("x_per_mm") || j.contains("y_per_mm") || j.contains("z_per_mm"));
    for (const auto& [key, value] : j.items()) {
        const bool known =
            byColour
                ? key == "transmitted_colour" || key == "extraordinary_transmitted_colour" || key == "path_mm"
            : byRays ? key == "wavelength_nm" || key == "x_per_mm" || key == "y_per_mm" || key == "z_per_mm"
                     : key == "wavelength_nm" || key == "ordinary_per_mm" || key == "extraordinary_per_mm";
        if (!known)
            throw Error(
                path + "." + key,
                "unknown field '" + path + "." + key +
                    (byColour ? "' (a colour by transmission has transmitted_colour, "
                                "extraordinary_transmitted_colour and path_mm)"
                     : byRays ? "' (a biaxial material's rays are wavelength_nm, x_per_mm, y_per_mm and "
                                "z_per_mm: their mean is the one spectrum)"
                              : "' (a spectrum has wavelength_nm, ordinary_per_mm and "
                                "extraordinary_per_mm, or x_per_mm, y_per_mm and z_per_mm for a "
                                "biaxial material, or is a colour by transmission: "
                                "transmitted_colour, or a corundum's chromophores: corundum_ppma)"));
    }
    if (byColour) return readTransmittedColour(j, path);
    const std::vector<const char*> required =
        byRays ? std::vector<const char*>{"wavelength_nm", "x_per_mm", "y_per_mm", "z_per_mm"}
               : std::vector<const char*>{"wavelength_nm", "ordinary_per_mm"};
    for (const char* key : required) {
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
    if (byRays) {
        const char* keys[3] = {"x_per_mm", "y_per_mm", "z_per_mm"};
        for (size_t axis = 0; axis < 3; ++axis)
            s.rayPerMm[axis] = readColumn(j[keys[axis]], path + "." + keys[axis], 0,
                                          AbsorptionSpectrum::kMaxPerMm, n, "coefficients per mm");
        s.ordinaryPerMm = AbsorptionSpectrum::meanOfRays(s.rayPerMm);
        return s;
    }
    s.ordinaryPerMm = readColumn(j["ordinary_per_mm"], path + ".ordinary_per_mm", 0,
                                 AbsorptionSpectrum::kMaxPerMm, n, "coefficients per mm");
    if (j.contains("extraordinary_per_mm"))
        s.extraordinaryPerMm = readColumn(j["extraordinary_per_mm"], path + ".extraordinary_per_mm", 0,
                                          AbsorptionSpectrum::kMaxPerMm, n, "coefficients per mm");
    return s;
}

std::string origin(const AbsorptionSpectrum& spectrum) {
    return spectrum.corundum ? describe(*spectrum.corundum) : "the job's absorption spectrum";
}

json toJson(const AbsorptionSpectrum& s) {
    if (s.corundum) return {{"corundum_ppma", {{"cr", s.corundum->crPpma}, {"fe_ti", s.corundum->feTiPpma}}}};
    if (s.trichroic())
        return {{"wavelength_nm", s.wavelengthNm},
                {"x_per_mm", s.rayPerMm[0]},
                {"y_per_mm", s.rayPerMm[1]},
                {"z_per_mm", s.rayPerMm[2]}};
    json j = {{"wavelength_nm", s.wavelengthNm}, {"ordinary_per_mm", s.ordinaryPerMm}};
    if (!s.extraordinaryPerMm.empty()) j["extraordinary_per_mm"] = s.extraordinaryPerMm;
    return j;
}

}  // namespace facetlight
