// GemCad's binary .gem: what a file states is read back (designs written here in the layout docs/optics.md
// gives), hostile bytes are refused with an Error, and each .gem in the real-design corpus states the same
// design as the .asc beside it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <random>

#include "io/gemcad_design.h"
#include "support/asc_facts.h"
#include "util/error.h"

using namespace facetlight;

namespace {

constexpr double kPi = 3.14159265358979323846;

void putI32(std::string& s, int32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(char((uint32_t(v) >> (8 * i)) & 0xff));
}
void putF64(std::string& s, double v) {
    uint64_t bits;
    std::memcpy(&bits, &v, 8);
    for (int i = 0; i < 8; ++i) s.push_back(char((bits >> (8 * i)) & 0xff));
}
void putText(std::string& s, const std::string& text) {
    s.push_back(char(text.size()));
    s += text;
}

// Writes a design the way GemCad lays out a .gem: per facet its plane (unit normal / distance), tier number,
// "name<TAB>instructions" and outline corners; then the settings and the 4 + 4 text slots. `tierNumber`
// numbers the tiers (GemCad: 1, 2, 3 ...).
std::string writeGem(
    const GemCadDesign& d,
    const std::function<int32_t(size_t)>& tierNumber = [](size_t t) { return int32_t(t + 1); }) {
    std::string s;
    for (size_t t = 0; t < d.tiers.size(); ++t) {
        const GemCadTier& tier = d.tiers[t];
        for (const GemCadFacet& f : tier.facets) {
            const double phi = 2 * kPi * (f.index - d.gearOffset) / d.gear;
            const double slope = std::fabs(tier.angleDeg) * kPi / 180;
            const double up = std::signbit(tier.angleDeg) ? -std::cos(slope) : std::cos(slope);
            const double n[3] = {std::sin(slope) * std::sin(phi), std::sin(slope) * std::cos(phi), up};
            for (double c : n) putF64(s, c / tier.distance);
            putI32(s, tierNumber(t));
            putText(s, f.name + "\t" + tier.instructions);
            for (int corner = 0; corner < 3; ++corner) {
                putI32(s, 1);
                for (double c : n) putF64(s, c * tier.distance * (1 + corner));
            }
            putI32(s, 0);
        }
    }
    putF64(s, -99999.0);
    putI32(s, d.symmetry);
    putI32(s, d.mirror ? 1 : 0);
    putI32(s, d.gear);
    putF64(s, d.refractiveIndex.value_or(0));
    putI32(s, 32767);
    putF64(s, d.gearOffset);
    for (int i = 0; i < 4; ++i) putText(s, i < int(d.headers.size()) ? d.headers[i] : "");
    for (int i = 0; i < 4; ++i) putText(s, i < int(d.footnotes.size()) ? d.footnotes[i] : "");
    return s;
}

GemCadTier tier(double angle, double distance, std::vector<double> indices, std::string name,
                std::string instructions = "") {
    GemCadTier t;
    t.angleDeg = angle;
    t.distance = distance;
    for (double i : indices) t.facets.push_back({i, t.facets.empty() ? name : ""});
    t.name = name;
    t.instructions = instructions;
    return t;
}

// A reversed 96 gear moved by 48 teeth, as in Strickland's designs, with every kind of tier.
GemCadDesign sampleDesign() {
    GemCadDesign d;
    d.gear = -96;
    d.gearOffset = 48;
    d.symmetry = 3;
    d.mirror = true;
    d.refractiveIndex = 1.76;
    d.headers = {"13.110 Sample", "by nobody", " "};
    d.footnotes = {"Written by the test"};
    d.tiers = {tier(-0.0, 0.2, {0}, "K"),
               tier(-46, 0.52522447, {0, 64, 32}, "P1", "Meet at the culet"),
               tier(-90, 0.79986259, {94, 66, 62, 34, 30, 2}, "G1"),
               tier(41.36, 0.61241081, {2, 30, 34, 62, 66, 94}, "A"),
               tier(10, 0.43163610, {1.57, 32, 64}, "E"),
               tier(0, 0.3, {0}, "T")};
    return d;
}

GemCadDesign parse(const std::string& bytes, const MeshLimits& limits = {}) {
    return parseGemCadBinary(bytes, limits);
}

std::string errorOf(const std::string& bytes, const MeshLimits& limits = {}) {
    try {
        parse(bytes, limits);
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

// Index equality on a gear of `teeth`: 96 and -96 are tooth 0.
double onGear(double index, double teeth) {
    const double i = std::fmod(index, teeth);
    return i < 0 ? i + teeth : i;
}

}  // namespace

TEST(GemCadBinary, ReadsBackWhatItStates) {
    const GemCadDesign want = sampleDesign();
    const GemCadDesign got = parse(writeGem(want));
    EXPECT_EQ(got.gear, -96);
    EXPECT_EQ(got.gearOffset, 48);
    EXPECT_EQ(got.symmetry, 3);
    EXPECT_TRUE(got.mirror);
    ASSERT_TRUE(got.refractiveIndex.has_value());
    EXPECT_EQ(*got.refractiveIndex, 1.76);
    EXPECT_EQ(got.headers, want.headers);
    EXPECT_EQ(got.footnotes, want.footnotes);
    EXPECT_TRUE(got.warnings.empty());
    ASSERT_EQ(got.tiers.size(), want.tiers.size());
    for (size_t t = 0; t < want.tiers.size(); ++t) {
        SCOPED_TRACE("tier " + want.tiers[t].name);
        const GemCadTier& a = want.tiers[t];
        const GemCadTier& b = got.tiers[t];
        EXPECT_NEAR(b.angleDeg, a.angleDeg, 1e-9);
        EXPECT_EQ(b.pavilion(), a.pavilion());
        EXPECT_NEAR(b.distance, a.distance, 1e-12);
        EXPECT_EQ(b.name, a.name);
        EXPECT_EQ(b.instructions, a.instructions);
        ASSERT_EQ(b.facets.size(), a.facets.size());
        for (size_t f = 0; f < a.facets.size(); ++f) {
            // A level facet has no azimuth: it reads as tooth 0 whatever the file's writer chose.
            const double want_index = a.angleDeg == 0 ? 0 : a.facets[f].index;
            EXPECT_NEAR(b.facets[f].index, want_index, 1e-9) << "facet " << f;
            EXPECT_EQ(b.facets[f].name, a.facets[f].name);
        }
    }
    EXPECT_TRUE(std::signbit(got.tiers.front().angleDeg)) << "the culet (-0) must stay on the pavilion";
    EXPECT_GT(got.distancePrecision, 0);
}

TEST(GemCadBinary, EveryTruncationIsAnError) {
    const std::string bytes = writeGem(sampleDesign());
    for (size_t n = 0; n < bytes.size(); ++n) {
        const std::string message = errorOf(bytes.substr(0, n));
        ASSERT_NE(message, "(no error)") << "cut to " << n << " bytes";
        ASSERT_NE(message.find("GemCad .gem"), std::string::npos) << message;
    }
}

// Each hostile value in its field is refused with a message that names it.
TEST(GemCadBinary, RefusesHostileFields) {
    const std::string good = writeGem(sampleDesign());
    const size_t trailer = good.find(std::string("\x00\x00\x00\x00\xf0\x69\xf8\xc0", 8));
    ASSERT_NE(trailer, std::string::npos);
    const auto putI32At = [](std::string s, size_t at, int32_t v) {
        std::string b;
        putI32(b, v);
        return s.replace(at, 4, b);
    };
    const auto putF64At = [](std::string s, size_t at, double v) {
        std::string b;
        putF64(b, v);
        return s.replace(at, 8, b);
    };
    const struct {
        const char* what;
        std::string bytes;
        const char* message;
    } cases[] = {
        {"tier 0", putI32At(good, 24, 0), "tier number 0"},
        {"tier skipped", putI32At(good, 24, 3), "tier number 3"},
        {"first tier 2", putI32At(good, 24, 2), "tier number 2"},
        {"outline flag", putI32At(good, 24 + 4 + 1 + 2, 7), "expected 0 or 1"},
        {"NaN plane", putF64At(good, 0, std::nan("")), "not a finite number"},
        {"zero plane", putF64At(putF64At(putF64At(good, 0, 0), 8, 0), 16, 0), "no direction"},
        {"far plane", putF64At(putF64At(putF64At(good, 0, 1e-300), 8, 0), 16, 0), "out of range"},
        {"near plane", putF64At(good, 0, 1e300), "out of range"},
        {"no facets", good.substr(trailer), "no facets"},
        {"symmetry 0", putI32At(good, trailer + 8, 0), "the symmetry 0"},
        {"mirror 2", putI32At(good, trailer + 12, 2), "mirror"},
        {"gear 0", putI32At(good, trailer + 16, 0), "the gear 0"},
        {"gear huge", putI32At(good, trailer + 16, 1 << 30), "teeth"},
        {"index NaN", putF64At(good, trailer + 20, std::nan("")), "refractive index"},
        {"offset inf", putF64At(good, trailer + 32, INFINITY), "gear offset"},
        {"text too long", good.substr(0, good.size() - 1) + "\xff", "footnotes"},
    };
    for (const auto& c : cases) {
        const std::string message = errorOf(c.bytes);
        EXPECT_NE(message.find(c.message), std::string::npos) << c.what << ": " << message;
    }
    MeshLimits few;
    few.maxPolygons = 5;
    EXPECT_NE(errorOf(good, few).find("more than 5 facets"), std::string::npos) << errorOf(good, few);
}

TEST(GemCadBinary, TierFacetsMustShareTheirPlaneFamily) {
    // Tiers P1 (-46 degrees) and G1 (-90) written as one tier: a tier's facets must share angle and distance.
    GemCadDesign d = sampleDesign();
    d.tiers = {d.tiers[1], d.tiers[2]};
    const std::string message = errorOf(writeGem(d, [](size_t) { return 1; }));
    EXPECT_NE(message.find("different angles"), std::string::npos) << message;
}

TEST(GemCadBinary, TrailingPreformIsAWarning) {
    std::string bytes = writeGem(sampleDesign());
    const GemCadDesign plain = parse(bytes);
    EXPECT_TRUE(plain.warnings.empty());
    const GemCadDesign withPreform = parse(bytes + "\x07preform" + std::string(40, '\x01'));
    ASSERT_EQ(withPreform.warnings.size(), 1u);
    EXPECT_NE(withPreform.warnings[0].find("preform"), std::string::npos) << withPreform.warnings[0];
    EXPECT_EQ(withPreform.tiers.size(), plain.tiers.size());
}

// Random damage gives a design or an Error, never another exception (the sanitizer build catches reads
// past the end).
TEST(GemCadBinary, RandomDamageGivesAnErrorOrADesign) {
    std::vector<std::string> seeds = {writeGem(sampleDesign())};
    for (const auto& path : test::corpusFiles(".gem")) seeds.push_back(test::readWholeFile(path));
    std::mt19937 random(27);
    for (const std::string& seed : seeds) {
        for (int trial = 0; trial < 2000; ++trial) {
            std::string bytes = seed;
            const int flips = 1 + int(random() % 4);
            for (int i = 0; i < flips; ++i) bytes[random() % bytes.size()] = char(random());
            try {
                parse(bytes);
            } catch (const Error&) {
            }
        }
    }
}

// The corpus's .asc/.gem pairs (the same design saved both ways by GemCad) state the same design.
TEST(GemCadBinary, CorpusPairsAgreeWithTheirAsc) {
    size_t pairs = 0;
    for (const auto& gemPath : test::corpusFiles(".gem")) {
        std::filesystem::path ascPath = gemPath;
        ascPath.replace_extension(".asc");
        if (!std::filesystem::exists(ascPath)) continue;
        ++pairs;
        SCOPED_TRACE(gemPath.filename().string());
        const test::AscFacts asc = test::readAscFacts(test::readWholeFile(ascPath));
        const std::string bytes = test::readWholeFile(gemPath);
        GemCadDesign gem;
        ASSERT_NO_THROW(gem = parse(bytes));
        EXPECT_TRUE(gem.warnings.empty()) << gem.warnings.front();
        EXPECT_EQ(gem.gear, asc.gear);
        EXPECT_EQ(gem.gearOffset, asc.gearOffset);
        EXPECT_EQ(gem.symmetry, asc.symmetry);
        EXPECT_EQ(gem.mirror, asc.mirror);
        ASSERT_EQ(gem.refractiveIndex.has_value(), asc.refractiveIndex.has_value());
        if (asc.refractiveIndex) {
            EXPECT_NEAR(*gem.refractiveIndex, *asc.refractiveIndex, 1e-12);
        }
        EXPECT_EQ(gem.headers, asc.headers);
        EXPECT_EQ(gem.footnotes, asc.footnotes);
        ASSERT_EQ(gem.tiers.size(), asc.tiers.size());
        size_t facets = 0;
        const double teeth = std::fabs(asc.gear);
        for (size_t t = 0; t < asc.tiers.size(); ++t) {
            SCOPED_TRACE("tier " + std::to_string(t + 1));
            const test::AscTierFacts& a = asc.tiers[t];
            const GemCadTier& g = gem.tiers[t];
            EXPECT_NEAR(g.angleDeg, a.angleDeg, a.anglePrecision + 1e-9);
            EXPECT_EQ(g.pavilion(), std::signbit(a.angleDeg));
            EXPECT_NEAR(g.distance, a.distance, a.distancePrecision + 1e-12);
            ASSERT_EQ(g.facets.size(), a.indices.size());
            for (size_t f = 0; f < a.indices.size(); ++f) {
                EXPECT_NEAR(onGear(g.facets[f].index, teeth), onGear(a.indices[f], teeth), 1e-9)
                    << "facet " << f;
                EXPECT_EQ(g.facets[f].name, a.names[f]) << "facet " << f;
            }
            facets += g.facets.size();
        }
        EXPECT_EQ(facets, asc.facetCount());
        // A real file cut short anywhere is refused, never read as a smaller design.
        for (size_t n = 0; n < bytes.size(); n += 7) EXPECT_THROW(parse(bytes.substr(0, n)), Error) << n;
    }
    if (pairs == 0) GTEST_SKIP() << "no .asc/.gem pairs in the corpus (tests/data/gemcad/SOURCES.md)";
}
