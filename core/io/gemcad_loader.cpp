// GemCad .asc designs: each tier line gives a slope angle, a distance and the index-gear positions of its
// facets; the stone is the intersection of all the facets' half-spaces.
//
// Conventions (docs/optics.md): the angle is the facet's slope from the girdle plane, 0 the table, 90 the
// girdle, negative (including "-0", a culet) on the pavilion; its outward normal is tilted |angle| from +z
// (from -z on the pavilion). Index i on a g-tooth gear with offset o has azimuth phi = 360 (i - o) / g,
// measured clockwise seen from above, from +y: index 0 points to +y, index g/4 to +x. So the horizontal
// part of the normal is sin|angle| (sin phi, cos phi).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "geometry/halfspace.h"
#include "io/mesh_io.h"
#include "util/error.h"
#include "util/excerpt.h"
#include "util/number_text.h"

namespace facetlight {

namespace {

// Real designs have a few hundred facets; the cap keeps the quadratic clipping bounded on hostile input.
constexpr size_t kMaxDesignFacets = 4096;
constexpr long long kMaxGear = 3600;
constexpr size_t kMaxWarnings = 10;

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

struct PlannedFacet {
    double index;
    std::string name;  // the tier's name until numbering
};

class GemCadParser {
  public:
    explicit GemCadParser(const MeshLimits& limits) : limits_(limits) {}

    PolygonMesh parse(std::string_view text) {
        size_t pos = 0;
        bool sawHeader = false;
        while (pos <= text.size()) {
            const size_t end = std::min(text.find('\n', pos), text.size());
            ++line_;
            const std::vector<std::string_view> words = splitWords(text.substr(pos, end - pos));
            pos = end + 1;
            if (words.empty()) continue;
            if (!sawHeader) {
                if (!startsWithIgnoreCase(words[0], "GemCad"))
                    throw Error(where() + "not a GemCad design: it must begin with a 'GemCad' header line");
                sawHeader = true;
                continue;
            }
            parseLine(words);
        }
        if (!sawHeader) throw Error("not a GemCad design: the file is empty");
        if (tiers_ == 0) throw Error("the GemCad design has no tiers ('a' lines)");
        return build();
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
        if (++warningCount_ <= kMaxWarnings) warnings_.push_back(std::move(message));
    }

    void parseLine(const std::vector<std::string_view>& words) {
        const std::string_view kind = words[0];
        if (kind == "g") {
            if (words.size() < 2) throw Error(where() + "the gear line needs the number of teeth");
            long long teeth = 0;
            if (!parseInteger(words[1], teeth) || teeth <= 0 || teeth > kMaxGear)
                throw Error(where() + "the gear " + inQuotes(words[1]) +
                            " must be a whole number of teeth from 1 to " + std::to_string(kMaxGear));
            gear_ = double(teeth);
            gearOffset_ = words.size() > 2 ? number(words[2], "the gear offset") : 0.0;
        } else if (kind == "y") {
            long long symmetry = 0;
            if (words.size() < 2 || !parseInteger(words[1], symmetry) || symmetry <= 0)
                throw Error(where() + "the symmetry line needs a positive whole number");
        } else if (kind == "I") {
            if (words.size() < 2 || !(number(words[1], "the refractive index") > 0))
                throw Error(where() + "the refractive index must be a positive number");
        } else if (kind == "a") {
            parseTier(words);
        } else if (kind != "H" && kind != "F") {
            warn(where() + "ignored a line of unknown kind " + inQuotes(kind));
        }
    }

    void parseTier(const std::vector<std::string_view>& words) {
        if (!(gear_ > 0)) throw Error(where() + "a tier comes before the gear line ('g <teeth> <offset>')");
        if (words.size() < 3) throw Error(where() + "a tier needs an angle and a distance");
        const double angle = number(words[1], "the angle");
        const double distance = number(words[2], "the distance");
        if (std::fabs(angle) > 90) throw Error(where() + "the angle must lie between -90 and 90 degrees");
        if (!(distance > 0)) throw Error(where() + "the distance must be positive");
        ++tiers_;

        std::vector<PlannedFacet> facets;
        std::string tierName;
        for (size_t i = 3; i < words.size(); ++i) {
            if (words[i] == "n") {
                if (i + 1 >= words.size()) throw Error(where() + "'n' must be followed by a name");
                const std::string name(words[++i]);
                if (tierName.empty()) tierName = name;
                if (!facets.empty() && facets.back().name.empty()) facets.back().name = name;
            } else if (looksNumeric(words[i])) {
                const double index = number(words[i], "the index");
                if (index < 0 || index > gear_)
                    throw Error(where() + "index " + std::string(words[i]) + " is not on the " +
                                std::to_string(int(gear_)) + "-tooth gear");
                facets.push_back({index, {}});
            } else {
                break;  // cutting instructions (G, F, ...) run to the end of the line
            }
        }
        if (facets.empty()) {
            // A table or culet needs no index; any other tier without one is a mistake.
            if (angle != 0) throw Error(where() + "the tier lists no index");
            facets.push_back({0, {}});
        }
        if (tierName.empty()) tierName = "tier" + std::to_string(tiers_);
        for (auto& f : facets) {
            if (planes_.size() >= std::min(limits_.maxPolygons, kMaxDesignFacets))
                throw Error(where() + "the design has more than " +
                            std::to_string(std::min(limits_.maxPolygons, kMaxDesignFacets)) + " facets");
            if (f.name.empty()) f.name = tierName;
            const double phi = 2 * kPi * (f.index - gearOffset_) / gear_;
            const double slope = radians(std::fabs(angle));
            const double up = std::signbit(angle) ? -std::cos(slope) : std::cos(slope);
            const Vec3 normal{std::sin(slope) * std::sin(phi), std::sin(slope) * std::cos(phi), up};
            planes_.push_back({{normal, distance}, f.name});
            planeLines_.push_back(line_);
        }
    }

    // Numbers facets per name across the file (P1_1 ... P1_8), a lone facet keeps its bare name (T).
    void nameFacets() {
        std::map<std::string, size_t> total, seen;
        for (const auto& p : planes_) ++total[p.name];
        for (auto& p : planes_)
            if (total[p.name] > 1) p.name += "_" + std::to_string(++seen[p.name]);
    }

    PolygonMesh build() {
        nameFacets();
        PolygonMesh mesh;
        try {
            mesh = intersectHalfSpaces(planes_);
        } catch (const Error& e) {
            const std::string message = e.what();
            for (size_t i = 0; i < planes_.size(); ++i)
                if (message.find("'" + planes_[i].name + "'") != std::string::npos)
                    throw Error("GemCad line " + std::to_string(planeLines_[i]) + ": " + message);
            throw Error("the GemCad design does not make a stone: " + message);
        }
        std::map<std::string, bool> present;
        for (const auto& poly : mesh.polygons) present[poly.name] = true;
        for (size_t i = 0; i < planes_.size(); ++i)
            if (!present.count(planes_[i].name))
                warn("GemCad line " + std::to_string(planeLines_[i]) + ": facet " + planes_[i].name +
                     " does not reach the stone's surface");
        if (warningCount_ > kMaxWarnings)
            warnings_.push_back(std::to_string(warningCount_ - kMaxWarnings) + " more GemCad warnings");
        mesh.warnings = std::move(warnings_);
        return mesh;
    }

    const MeshLimits& limits_;
    size_t line_ = 0;
    double gear_ = 0, gearOffset_ = 0;
    int tiers_ = 0;
    std::vector<NamedPlane> planes_;
    std::vector<size_t> planeLines_;
    std::vector<std::string> warnings_;
    size_t warningCount_ = 0;
};

}  // namespace

PolygonMesh parseGemCad(std::string_view text, const MeshLimits& limits) {
    return GemCadParser(limits).parse(text);
}

}  // namespace facetlight
