// GemCad's binary .gem project files, read into the same GemCadDesign as an .asc text (layout:
// docs/optics.md, "GemCad binary .gem"). The file stores each facet as its plane and outline rather than as
// angle, index and distance, so those are measured back from the plane: the design's frame and GemCad's are
// the same (x = sin phi, y = cos phi of the azimuth, +z up), so no rotation is involved.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>

#include "io/gemcad_design.h"
#include "io/mesh_io.h"
#include "util/error.h"

namespace facetlight {

namespace {

// The "normal" that ends the facet records: GemCad writes it where the next facet's plane would begin.
constexpr double kEndOfFacets = -99999.0;
// As for .asc designs: real ones have a few hundred facets, and the mesh builder is quadratic in them.
constexpr size_t kMaxDesignFacets = 4096;
constexpr int32_t kMaxGear = 3600;
constexpr int32_t kMaxSymmetry = 3600;
// Header lines, then as many footnote lines, each a slot that may be empty.
constexpr int kTextSlots = 4;
// A level facet (table, culet) has no azimuth; below this horizontal share of its normal it is level.
constexpr double kLevel = 1e-12;
// Indices this close to a whole tooth are that tooth (the planes are doubles computed from whole indices).
constexpr double kWholeTooth = 1e-6;

constexpr double kPi = 3.14159265358979323846;
double degrees(double radians) {
    return radians * 180 / kPi;
}

// Little-endian reads that never pass the end: each names what it was reading when the bytes ran out.
class ByteReader {
  public:
    explicit ByteReader(std::string_view bytes) : bytes_(bytes) {}

    size_t offset() const { return pos_; }
    size_t left() const { return bytes_.size() - pos_; }

    int32_t int32(const char* what) {
        need(4, what);
        uint32_t v = 0;
        for (int i = 0; i < 4; ++i) v |= uint32_t(uint8_t(bytes_[pos_ + i])) << (8 * i);
        pos_ += 4;
        return int32_t(v);
    }

    double float64(const char* what) {
        const double v = peekFloat64(what);
        pos_ += 8;
        return v;
    }

    double peekFloat64(const char* what) const {
        need(8, what);
        uint64_t bits = 0;
        for (int i = 0; i < 8; ++i) bits |= uint64_t(uint8_t(bytes_[pos_ + i])) << (8 * i);
        double v;
        std::memcpy(&v, &bits, 8);
        return v;
    }

    // A text of at most 255 bytes: its length in one byte, then the bytes.
    std::string text(const char* what) {
        need(1, what);
        const size_t length = uint8_t(bytes_[pos_]);
        need(1 + length, what);
        std::string s(bytes_.substr(pos_ + 1, length));
        pos_ += 1 + length;
        return s;
    }

    bool startsWithText(std::string_view text) const {
        return left() > text.size() && uint8_t(bytes_[pos_]) == text.size() &&
               bytes_.substr(pos_ + 1, text.size()) == text;
    }

    void skip(size_t n, const char* what) {
        need(n, what);
        pos_ += n;
    }

  private:
    void need(size_t n, const char* what) const {
        if (left() < n)
            throw Error("GemCad .gem: the file ends at byte " + std::to_string(bytes_.size()) + ", inside " +
                        what);
    }

    std::string_view bytes_;
    size_t pos_ = 0;
};

// A facet as the file states it, before the gear (which comes last in the file) turns azimuths into indices.
struct FacetRecord {
    int32_t tier;
    double angleDeg;
    double distance;
    std::optional<double> azimuthDeg;  // none for a level facet
    std::string name;
    std::string instructions;
};

// Two facets of one tier: the same signed slope, except that a vertical facet's sign is only rounding.
bool sameSlope(double a, double b) {
    constexpr double kTolerance = 1e-6;
    if (std::fabs(std::fabs(a) - 90) < kTolerance && std::fabs(std::fabs(b) - 90) < kTolerance) return true;
    return std::fabs(a - b) < kTolerance;
}

std::string shortNumber(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::string trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return std::string(s);
}

class GemCadBinaryParser {
  public:
    GemCadBinaryParser(std::string_view bytes, const MeshLimits& limits) : in_(bytes), limits_(limits) {}

    GemCadDesign parse() {
        std::vector<FacetRecord> facets;
        const size_t maxFacets = std::min(limits_.maxPolygons, kMaxDesignFacets);
        while (in_.peekFloat64("a facet record or the design's settings") != kEndOfFacets) {
            if (facets.size() >= maxFacets)
                throw Error("GemCad .gem: the design has more than " + std::to_string(maxFacets) + " facets");
            facets.push_back(facet(facets.empty() ? 0 : facets.back().tier));
        }
        if (facets.empty()) throw Error("GemCad .gem: the design has no facets");
        GemCadDesign design;
        settings(design);
        texts(design);
        tiers(design, facets);
        double maxDistance = 0;
        for (const auto& t : design.tiers) maxDistance = std::max(maxDistance, t.distance);
        // The planes are doubles, not printed decimals: meets are exact to far better than this.
        design.distancePrecision = 1e-9 * maxDistance;
        return design;
    }

  private:
    std::string at(size_t offset) const { return "GemCad .gem, byte " + std::to_string(offset) + ": "; }

    // One facet: its plane as n / d (n the outward unit normal, d the distance), its tier's number, its name
    // and cutting instructions, then its outline's corners (not needed: the planes make the stone).
    FacetRecord facet(int32_t previousTier) {
        const size_t start = in_.offset();
        double n[3];
        for (double& c : n) c = in_.float64("a facet's plane");
        const int32_t tier = in_.int32("a facet's tier number");
        if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2]))
            throw Error(at(start) + "a facet's plane is not a finite number");
        const double length = std::hypot(std::hypot(n[0], n[1]), n[2]);
        if (!(length > 0)) throw Error(at(start) + "a facet's plane has no direction");
        const double distance = 1 / length;
        if (!(distance <= kMaxMeshCoordinate) || !(distance >= kMinMeshExtent))
            throw Error(at(start) + "a facet's distance from the centre, " + shortNumber(distance) +
                        ", is out of range");
        if (tier < std::max(previousTier, 1) || tier > previousTier + 1)
            throw Error(at(start + 24) + "tier number " + std::to_string(tier) + " after tier " +
                        std::to_string(previousTier) + ": the tiers must be numbered 1, 2, 3 ... in order");

        FacetRecord f{tier, 0, distance, std::nullopt, {}, {}};
        const double horizontal = std::hypot(n[0], n[1]);
        const double slope = degrees(std::atan2(horizontal, std::fabs(n[2])));
        f.angleDeg = std::signbit(n[2]) ? -slope : slope;  // -0 (a culet) stays on the pavilion
        if (horizontal > kLevel * length) {
            const double phi = degrees(std::atan2(n[0], n[1]));
            f.azimuthDeg = phi < 0 ? phi + 360 : phi;
        }
        const std::string label = in_.text("a facet's name");
        const size_t tab = label.find('\t');
        f.name = trim(label.substr(0, tab));
        if (tab != std::string::npos) f.instructions = trim(std::string_view(label).substr(tab + 1));

        // Each corner is followed by a flag: 1 when another corner follows, 0 after the last.
        const char* corner = "a facet's outline";
        for (int32_t more = flag(corner); more; more = flag(corner)) in_.skip(24, corner);
        return f;
    }

    int32_t flag(const char* what) {
        const size_t offset = in_.offset();
        const int32_t v = in_.int32(what);
        if (v != 0 && v != 1)
            throw Error(at(offset) + "expected 0 or 1 in " + what + ", found " + std::to_string(v));
        return v;
    }

    // After the facets: the end mark, the symmetry, the mirror flag, the gear, the refractive index, a field
    // not known (32767 in every file seen) and the gear's offset in teeth.
    void settings(GemCadDesign& design) {
        in_.float64("the end of the facets");
        size_t offset = in_.offset();
        const int32_t symmetry = in_.int32("the symmetry");
        if (symmetry < 1 || symmetry > kMaxSymmetry)
            throw Error(at(offset) + "the symmetry " + std::to_string(symmetry) + " must be from 1 to " +
                        std::to_string(kMaxSymmetry));
        design.symmetry = symmetry;
        design.mirror = flag("the mirror-symmetry flag") == 1;
        offset = in_.offset();
        const int32_t gear = in_.int32("the gear");
        if (gear == 0 || gear > kMaxGear || gear < -kMaxGear)
            throw Error(at(offset) + "the gear " + std::to_string(gear) + " must have from 1 to " +
                        std::to_string(kMaxGear) + " teeth (negative: numbered the other way round)");
        design.gear = gear;
        offset = in_.offset();
        const double index = in_.float64("the refractive index");
        if (!std::isfinite(index) || index < 0 || index > 100)
            throw Error(at(offset) + "the refractive index " + std::to_string(index) +
                        " is not a valid index");
        if (index > 0) design.refractiveIndex = index;
        in_.skip(4, "the design's settings");
        offset = in_.offset();
        design.gearOffset = in_.float64("the gear offset");
        if (!std::isfinite(design.gearOffset) || std::fabs(design.gearOffset) > kMaxGear)
            throw Error(at(offset) + "the gear offset is not a valid number of teeth");
    }

    // The header lines, then the footnotes; empty slots are lines the designer left blank. A "preform" (the
    // rough GemCad cuts the design from) may follow; the design does not need it.
    void texts(GemCadDesign& design) {
        for (int i = 0; i < 2 * kTextSlots; ++i) {
            std::string line = in_.text(i < kTextSlots ? "the header lines" : "the footnotes");
            if (line.empty()) continue;
            (i < kTextSlots ? design.headers : design.footnotes).push_back(std::move(line));
        }
        if (in_.left() == 0) return;
        design.warnings.push_back(at(in_.offset()) + (in_.startsWithText("preform")
                                                          ? "the preform after the design was not read"
                                                          : std::to_string(in_.left()) +
                                                                " bytes after the footnotes were not read"));
    }

    // Groups the facets into their tiers and turns azimuths into indices on the design's gear.
    void tiers(GemCadDesign& design, const std::vector<FacetRecord>& facets) const {
        const double teeth = std::abs(design.gear);
        for (size_t i = 0; i < facets.size(); ++i) {
            const FacetRecord& f = facets[i];
            if (i == 0 || f.tier != facets[i - 1].tier) {
                GemCadTier tier;
                tier.angleDeg = f.angleDeg;
                tier.distance = f.distance;
                design.tiers.push_back(std::move(tier));
            }
            GemCadTier& tier = design.tiers.back();
            if (!sameSlope(f.angleDeg, tier.angleDeg) ||
                std::fabs(f.distance - tier.distance) > 1e-9 * tier.distance)
                throw Error("GemCad .gem: tier " + std::to_string(f.tier) +
                            " has facets at different angles or distances (" + shortNumber(tier.angleDeg) +
                            " and " + shortNumber(f.angleDeg) + " degrees)");
            double index = 0;
            if (f.azimuthDeg) {
                // phi = 360 (i - o) / g, so i = o + g phi / 360, brought onto the gear's teeth 0 .. |g|.
                index = std::fmod(design.gearOffset + design.gear * *f.azimuthDeg / 360, teeth);
                if (index < 0) index += teeth;
                if (std::fabs(index - std::round(index)) < kWholeTooth) index = std::round(index);
                if (index >= teeth) index -= teeth;
            }
            tier.facets.push_back({index, f.name});
            if (tier.name.empty()) tier.name = f.name;
            if (tier.instructions.empty()) tier.instructions = f.instructions;
        }
        for (size_t k = 0; k < design.tiers.size(); ++k)
            if (design.tiers[k].name.empty()) design.tiers[k].name = "tier" + std::to_string(k + 1);
    }

    ByteReader in_;
    const MeshLimits& limits_;
};

}  // namespace

bool looksLikeGemCadBinary(std::string_view bytes) {
    // The first facet record: a finite plane, tier number 1, a name, an outline flag of 0 or 1.
    try {
        ByteReader in(bytes);
        double n[3];
        for (double& c : n) c = in.float64("");
        if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2])) return false;
        if (std::hypot(std::hypot(n[0], n[1]), n[2]) == 0 || in.int32("") != 1) return false;
        in.text("");
        const int32_t outline = in.int32("");
        return outline == 0 || outline == 1;
    } catch (const Error&) {
        return false;
    }
}

GemCadDesign parseGemCadBinary(std::string_view bytes, const MeshLimits& limits) {
    return GemCadBinaryParser(bytes, limits).parse();
}

}  // namespace facetlight
