// GemCad .asc designs (io/gemcad_design.h). The reading rules, checked against real published designs
// (tests/data/gemcad/SOURCES.md), are set out in docs/optics.md, "GemCad designs".
#include "io/gemcad_design.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "util/error.h"
#include "util/excerpt.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

// Real designs have a few hundred facets; the cap keeps the quadratic clipping bounded on hostile input.
constexpr size_t kMaxDesignFacets = 4096;
constexpr long long kMaxGear = 3600;
constexpr size_t kMaxWarnings = 10;
// GemCad writes distances with 6 to 8 decimals; fewer were typed by hand and are taken as exact.
constexpr int kFewestWrittenDecimals = 4;
// Where several facets meet at one point, the printed distances put their planes' common points up to a few
// times the printing error apart (more where two planes cross at a small angle); closer vertices are one meet.
constexpr double kMeetsPerPrintingError = 20;
// GemCad finds the distances that make facets meet in single precision (a float's 6e-8 of the size, times the
// same geometry): Strickland's Compear 1:1.25 puts the 13 planes of its culet up to 3e-6 of its size apart,
// whatever its 8 printed decimals say. Vertices closer than this share of the size are one meet too.
constexpr double kMeetShareOfSize = 1e-5;

bool validUtf8(std::string_view s) {
    size_t i = 0;
    while (i < s.size()) {
        const auto c = uint8_t(s[i]);
        const size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
        if (n == 0 || i + n > s.size()) return false;
        for (size_t k = 1; k < n; ++k)
            if ((uint8_t(s[i + k]) & 0xC0) != 0x80) return false;
        i += n;
    }
    return true;
}

// The text as UTF-8: a byte-order mark dropped; a file that is not UTF-8 read as Windows-1252, which GemCad for
// Windows writes (its degree sign is byte 0xB0). Bytes 0x80-0x9F, punctuation there, become '?'.
std::string asUtf8(std::string_view bytes) {
    if (bytes.substr(0, 3) == "\xEF\xBB\xBF") bytes.remove_prefix(3);
    if (validUtf8(bytes)) return std::string(bytes);
    std::string out;
    out.reserve(bytes.size() + bytes.size() / 8);
    for (char ch : bytes) {
        const auto c = uint8_t(ch);
        if (c < 0x80) {
            out += ch;
        } else if (c < 0xA0) {
            out += '?';
        } else {
            out += char(0xC0 | (c >> 6));
            out += char(0x80 | (c & 0x3F));
        }
    }
    return out;
}

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    size_t pos = 0;
    while (pos < line.size()) {
        while (pos < line.size() && std::isspace(uint8_t(line[pos]))) ++pos;
        const size_t begin = pos;
        while (pos < line.size() && !std::isspace(uint8_t(line[pos]))) ++pos;
        if (pos > begin) words.push_back(line.substr(begin, pos - begin));
    }
    return words;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(uint8_t(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(uint8_t(s.back()))) s.remove_suffix(1);
    return s;
}

bool startsWithIgnoreCase(std::string_view s, std::string_view prefix) {
    if (s.size() < prefix.size()) return false;
    for (size_t i = 0; i < prefix.size(); ++i)
        if (std::tolower(uint8_t(s[i])) != std::tolower(uint8_t(prefix[i]))) return false;
    return true;
}

bool looksNumeric(std::string_view word) {
    const char c = word[0];
    return std::isdigit(uint8_t(c)) || c == '+' || c == '-' || c == '.';
}

// Half the last printed digit of a number written with at least kFewestWrittenDecimals decimals, else 0.
double printingError(std::string_view word) {
    const size_t dot = word.find('.');
    if (dot == std::string_view::npos || word.find_first_of("eE") != std::string_view::npos) return 0;
    const int decimals = int(word.size() - dot - 1);
    return decimals >= kFewestWrittenDecimals ? 0.5 * std::pow(10.0, -decimals) : 0;
}

class GemCadParser {
  public:
    explicit GemCadParser(const MeshLimits& limits) : limits_(limits) {}

    GemCadDesign parse(std::string_view bytes) {
        const std::string text = asUtf8(bytes);
        size_t pos = 0;
        bool sawHeader = false;
        while (pos <= text.size()) {
            size_t end = text.find_first_of("\r\n", pos);
            if (end == std::string::npos) end = text.size();
            ++line_;
            const std::string_view lineText = std::string_view(text).substr(pos, end - pos);
            pos = end + (text.compare(end, 2, "\r\n") == 0 ? 2 : 1);
            std::vector<std::string_view> words = splitWords(lineText);
            if (words.empty()) continue;
            if (!sawHeader) {
                if (!startsWithIgnoreCase(words[0], "GemCad"))
                    throw Error(where() + "not a GemCad design: it must begin with a 'GemCad' header line");
                sawHeader = true;
                continue;
            }
            parseLine(words, lineText);
        }
        if (!sawHeader) throw Error("not a GemCad design: the file is empty");
        finishTier();
        if (design_.tiers.empty()) throw Error("the GemCad design has no tiers ('a' lines)");
        if (warningCount_ > kMaxWarnings)
            design_.warnings.push_back(std::to_string(warningCount_ - kMaxWarnings) + " more GemCad warnings");
        return std::move(design_);
    }

  private:
    std::string where() const { return "GemCad line " + std::to_string(line_) + ": "; }

    double number(std::string_view word, const char* what) const {
        double value = 0;
        if (!parseNumber(word, value) || !std::isfinite(value))
            throw Error(where() + what + " " + inQuotes(word) + " is not a valid number");
        return value;
    }

    void warn(std::string message) {
        if (++warningCount_ <= kMaxWarnings) design_.warnings.push_back(std::move(message));
    }

    void parseLine(std::vector<std::string_view>& words, std::string_view lineText) {
        // A keyword glued to its number ("g96 0.0") is read as two words.
        if (words[0].size() > 1 && std::string_view("gyIa").find(words[0][0]) != std::string_view::npos &&
            looksNumeric(words[0].substr(1))) {
            const std::string_view glued = words[0];
            words[0] = glued.substr(0, 1);
            words.insert(words.begin() + 1, glued.substr(1));
        }
        const std::string_view kind = words[0];
        // A long index list continues on lines that start with an index, a name or cutting instructions.
        if (openTier_ && (looksNumeric(kind) || kind == "n" || kind == "G")) {
            readFacetWords(words, 0);
            return;
        }
        finishTier();
        // Some published files lack the gear line's keyword ("96 0.0" before the first tier).
        if (!sawGear_ && design_.tiers.empty() && looksNumeric(kind)) words.insert(words.begin(), "g");
        if (words[0] == "g") {
            if (words.size() < 2) throw Error(where() + "the gear line needs the number of teeth");
            long long teeth = 0;
            if (!parseInteger(words[1], teeth) || teeth == 0 || teeth > kMaxGear || teeth < -kMaxGear)
                throw Error(where() + "the gear " + inQuotes(words[1]) + " must be a whole number of teeth from 1 to " +
                            std::to_string(kMaxGear) + " (negative to number them the other way round)");
            design_.gear = int(teeth);
            design_.gearOffset = words.size() > 2 ? number(words[2], "the gear offset") : 0.0;
            sawGear_ = true;
        } else if (kind == "y") {
            long long symmetry = 0;
            if (words.size() < 2 || !parseInteger(words[1], symmetry) || symmetry <= 0 || symmetry > kMaxGear)
                throw Error(where() + "the symmetry line needs a positive whole number");
            design_.symmetry = int(symmetry);
            design_.mirror = words.size() > 2 && (words[2] == "y" || words[2] == "Y");
        } else if (kind == "I") {
            if (words.size() < 2) throw Error(where() + "the refractive index line needs a number");
            const double n = number(words[1], "the refractive index");
            if (!(n >= 1 && n <= 5))
                throw Error(where() + "the refractive index " + inQuotes(words[1]) + " must lie between 1 and 5");
            design_.refractiveIndex = n;
        } else if (kind == "H" || kind == "F") {
            const std::string text(trim(trim(lineText).substr(1)));
            (kind == "H" ? design_.headers : design_.footnotes).push_back(text);
        } else if (kind == "a") {
            startTier(words);
        } else {
            warn(where() + "ignored a line of unknown kind " + inQuotes(kind));
        }
    }

    void startTier(const std::vector<std::string_view>& words) {
        if (!sawGear_) throw Error(where() + "a tier comes before the gear line ('g <teeth> <offset>')");
        if (words.size() < 3) throw Error(where() + "a tier needs an angle and a distance");
        GemCadTier tier;
        tier.angleDeg = number(words[1], "the angle");
        tier.distance = number(words[2], "the distance");
        if (std::fabs(tier.angleDeg) > 90) throw Error(where() + "the angle must lie between -90 and 90 degrees");
        // GemCad's manual: the distance is positive unless the facet is a culet (a 0-degree pavilion facet).
        if (tier.angleDeg == 0 && tier.distance < 0) {
            tier.angleDeg = -0.0;
            tier.distance = -tier.distance;
        }
        if (!(tier.distance > 0)) throw Error(where() + "the distance must be positive");
        design_.distancePrecision = std::max(design_.distancePrecision, printingError(words[2]));
        tier.line = line_;
        design_.tiers.push_back(std::move(tier));
        openTier_ = true;
        readFacetWords(words, 3);
    }

    void readFacetWords(const std::vector<std::string_view>& words, size_t from) {
        GemCadTier& tier = design_.tiers.back();
        for (size_t i = from; i < words.size(); ++i) {
            if (words[i] == "n") {
                if (i + 1 >= words.size()) throw Error(where() + "'n' must be followed by a name");
                const std::string name(words[++i]);
                if (tier.name.empty()) tier.name = name;
                if (!tier.facets.empty() && tier.facets.back().name.empty()) tier.facets.back().name = name;
            } else if (looksNumeric(words[i])) {
                addFacet(tier, number(words[i], "the index"));
            } else {
                // Cutting instructions ("G ...") run to the end of the line.
                const size_t skip = words[i] == "G" ? i + 1 : i;
                for (size_t k = skip; k < words.size(); ++k) {
                    if (!tier.instructions.empty()) tier.instructions += ' ';
                    tier.instructions += words[k];
                }
                break;
            }
        }
    }

    void addFacet(GemCadTier& tier, double index) {
        const size_t cap = std::min(limits_.maxPolygons, kMaxDesignFacets);
        if (++facetCount_ > cap) throw Error(where() + "the design has more than " + std::to_string(cap) + " facets");
        tier.facets.push_back({index, {}});
    }

    void finishTier() {
        if (!openTier_) return;
        openTier_ = false;
        GemCadTier& tier = design_.tiers.back();
        if (tier.facets.empty()) {
            // A table or culet needs no index; any other tier without one is a mistake.
            if (tier.angleDeg != 0)
                throw Error("GemCad line " + std::to_string(tier.line) + ": the tier lists no index");
            addFacet(tier, 0);
        }
        if (tier.name.empty()) tier.name = "tier" + std::to_string(design_.tiers.size());
    }

    const MeshLimits& limits_;
    GemCadDesign design_;
    size_t line_ = 0;
    bool sawGear_ = false, openTier_ = false;
    size_t facetCount_ = 0;
    size_t warningCount_ = 0;
};

}  // namespace

GemCadDesign parseGemCadDesign(std::string_view text, const MeshLimits& limits) {
    return GemCadParser(limits).parse(text);
}

double gemCadAzimuthDeg(const GemCadDesign& design, double index) {
    const double phi = std::fmod(360.0 * (index - design.gearOffset) / design.gear, 360.0);
    return phi < 0 ? phi + 360.0 : phi;
}

Vec3 gemCadNormal(double angleDeg, double azimuthDeg) {
    const double slope = radians(std::fabs(angleDeg)), phi = radians(azimuthDeg);
    const double up = std::signbit(angleDeg) ? -std::cos(slope) : std::cos(slope);
    return {std::sin(slope) * std::sin(phi), std::sin(slope) * std::cos(phi), up};
}

std::vector<NamedPlane> gemCadPlanes(const GemCadDesign& design) {
    std::vector<NamedPlane> planes;
    for (const auto& tier : design.tiers)
        for (const auto& facet : tier.facets)
            planes.push_back({{gemCadNormal(tier.angleDeg, gemCadAzimuthDeg(design, facet.index)), tier.distance},
                              facet.name.empty() ? tier.name : facet.name});
    std::map<std::string, size_t> total, seen;
    for (const auto& p : planes) ++total[p.name];
    for (auto& p : planes)
        if (total[p.name] > 1) p.name += "_" + std::to_string(++seen[p.name]);
    return planes;
}

PolygonMesh buildGemCadMesh(const GemCadDesign& design, const MeshLimits& limits) {
    const std::vector<NamedPlane> planes = gemCadPlanes(design);
    if (planes.size() > limits.maxPolygons)
        throw Error("the design has more than " + std::to_string(limits.maxPolygons) + " facets");
    // "GemCad line 7: " before a message about a plane, where the file gave its tier's line.
    std::vector<size_t> planeLines;
    for (const auto& tier : design.tiers) planeLines.insert(planeLines.end(), tier.facets.size(), tier.line);
    auto lineOf = [&](size_t plane) {
        return planeLines[plane] ? "GemCad line " + std::to_string(planeLines[plane]) + ": " : std::string();
    };
    PolygonMesh mesh;
    try {
        double reach = 0;
        for (const GemCadTier& tier : design.tiers) reach = std::max(reach, tier.distance);
        mesh = intersectHalfSpaces(planes, std::max(kMeetsPerPrintingError * design.distancePrecision,
                                                    kMeetShareOfSize * reach));
    } catch (const Error& e) {
        const std::string message = e.what();
        for (size_t i = 0; i < planes.size(); ++i)
            if (message.find("'" + planes[i].name + "'") != std::string::npos) throw Error(lineOf(i) + message);
        throw Error("the GemCad design does not make a stone: " + message);
    }
    mesh.warnings = design.warnings;
    std::map<std::string, bool> present;
    for (const auto& poly : mesh.polygons) present[poly.name] = true;
    size_t missing = 0;
    for (size_t i = 0; i < planes.size(); ++i)
        if (!present.count(planes[i].name) && ++missing <= kMaxWarnings)
            mesh.warnings.push_back(lineOf(i) + "facet " + planes[i].name + " does not reach the stone's surface");
    if (missing > kMaxWarnings)
        mesh.warnings.push_back(std::to_string(missing - kMaxWarnings) + " more facets do not reach the surface");
    mesh.design = std::make_shared<const GemCadDesign>(design);
    return mesh;
}

}  // namespace facetlight
