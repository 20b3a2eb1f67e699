#pragma once
// What a GemCad .asc file states, read plainly for tests: the expectations the corpus tests hold the
// loaders to come from the file itself, not from the loader under test. Lenient where real files are
// (CRLF, continuation lines, a gear line without its "g", "g96" glued, "-0" or a negative distance for a
// culet); no checks, no geometry.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace facetlight::test {

struct AscTierFacts {
    double angleDeg = 0;  // signed; -0 for a culet
    double distance = 0;
    double anglePrecision = 0, distancePrecision = 0;  // half the last printed digit
    std::vector<double> indices;
    std::vector<std::string> names;  // per index: the name written after it, or empty
};

struct AscFacts {
    double gear = 96, gearOffset = 0;
    int symmetry = 1;
    bool mirror = false;
    std::optional<double> refractiveIndex;
    std::vector<std::string> headers, footnotes;
    std::vector<AscTierFacts> tiers;

    size_t facetCount() const {
        size_t n = 0;
        for (const auto& t : tiers) n += t.indices.size();
        return n;
    }
    // Degrees clockwise from +y, seen from above (docs/optics.md, "GemCad designs").
    double azimuthDeg(double index) const {
        const double phi = std::fmod(360 * (index - gearOffset) / gear, 360.0);
        return phi < 0 ? phi + 360 : phi;
    }
};

inline std::string readWholeFile(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

namespace detail {

inline std::vector<std::string> words(std::string_view line) {
    std::vector<std::string> out;
    std::istringstream in{std::string(line)};
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

inline bool isNumber(const std::string& w, double& value) {
    if (w.empty()) return false;
    char* end = nullptr;
    value = std::strtod(w.c_str(), &end);
    return end == w.c_str() + w.size();
}

// Half a unit of the last digit printed: "0.47054522" -> 5e-9, "41" -> 0.5.
inline double halfLastDigit(const std::string& w) {
    const size_t dot = w.find('.');
    const int decimals = dot == std::string::npos ? 0 : int(w.size() - dot - 1);
    return 0.5 * std::pow(10.0, -decimals);
}

}  // namespace detail

// A tier's indices and names, up to the first word that is neither (cutting instructions run to the end of
// the line). Returns false if it stopped at instructions.
inline bool readTierWords(AscTierFacts& tier, const std::vector<std::string>& w, size_t from) {
    double value = 0;
    for (size_t i = from; i < w.size(); ++i) {
        if (w[i] == "n" && i + 1 < w.size()) {
            if (!tier.names.empty() && tier.names.back().empty()) tier.names.back() = w[i + 1];
            ++i;
        } else if (detail::isNumber(w[i], value)) {
            tier.indices.push_back(value);
            tier.names.emplace_back();
        } else {
            return false;
        }
    }
    return true;
}

inline AscFacts readAscFacts(std::string_view text) {
    AscFacts facts;
    size_t pos = 0;
    bool first = true;
    while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        std::vector<std::string> w = detail::words(line);
        if (first || w.empty()) {  // the "GemCad 5.0" line
            first = first && w.empty();
            continue;
        }
        double value = 0;
        const std::string& kind = w[0];
        const bool gearLine = kind == "g" || (kind[0] == 'g' && detail::isNumber(kind.substr(1), value)) ||
                              (facts.tiers.empty() && detail::isNumber(kind, value));
        if (gearLine) {
            if (kind == "g")
                w.erase(w.begin());
            else if (kind[0] == 'g')
                w[0].erase(0, 1);  // "g96"
            if (!w.empty()) detail::isNumber(w[0], facts.gear);
            if (w.size() > 1) detail::isNumber(w[1], facts.gearOffset);
        } else if (kind == "y") {
            if (w.size() > 1) facts.symmetry = std::atoi(w[1].c_str());
            facts.mirror = w.size() > 2 && w[2] == "y";
        } else if (kind == "I") {
            if (w.size() > 1 && detail::isNumber(w[1], value)) facts.refractiveIndex = value;
        } else if (kind == "H" || kind == "F") {
            const std::string rest = line.size() > 2 ? std::string(line.substr(2)) : std::string();
            (kind == "H" ? facts.headers : facts.footnotes).push_back(rest);
        } else if (kind == "a") {
            AscTierFacts tier;
            if (w.size() > 2) {
                detail::isNumber(w[1], tier.angleDeg);
                detail::isNumber(w[2], tier.distance);
                tier.anglePrecision = detail::halfLastDigit(w[1]);
                tier.distancePrecision = detail::halfLastDigit(w[2]);
            }
            if (tier.angleDeg == 0 && tier.distance < 0) tier.angleDeg = -0.0;  // "a 0 -0.368 0": a culet
            tier.distance = std::fabs(tier.distance);
            readTierWords(tier, w, 3);
            facts.tiers.push_back(std::move(tier));
        } else if (!facts.tiers.empty() && kind != "G") {
            readTierWords(facts.tiers.back(), w, 0);  // indices or names continued on the next line
        }
    }
    for (auto& tier : facts.tiers) {
        if (tier.indices.empty()) {  // a table or culet may list no index
            tier.indices.push_back(0);
            tier.names.emplace_back();
        }
    }
    return facts;
}

// The corpus of real designs (tests/data/gemcad/SOURCES.md): the folder the build names, or
// $FACETLIGHT_GEMCAD_CORPUS; its files with the given extension, sorted.
inline std::vector<std::filesystem::path> corpusFiles(const std::string& extension) {
    namespace fs = std::filesystem;
    const char* env = std::getenv("FACETLIGHT_GEMCAD_CORPUS");
    const fs::path dir = env && *env ? fs::path(env) : fs::path(FACETLIGHT_GEMCAD_CORPUS);
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().extension() == extension) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace facetlight::test
