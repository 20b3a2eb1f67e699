// The real-design corpus (tests/data/gemcad, SOURCES.md) opens as each file states it (issue 27): loadStone
// gives as many facets as the file lists, each facet at its tier's angle and at the azimuth of its gear
// index, and the design is not turned (its table, if it has one, faces +z).
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <sstream>

#include "io/mesh_io.h"
#include "support/asc_facts.h"
#include "util/error.h"

using namespace facetlight;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kToleranceDeg = 0.01;

// What each design states, counted from its file; readAscFacts must count the same, so the test's own
// reading of a file is checked too. Every .asc in the corpus needs a row.
struct CorpusDesign {
    const char* file;
    size_t tiers;
    size_t facets;
    bool table;  // a tier at angle +0
};
const CorpusDesign kCorpus[] = {
    {"Compear125.asc", 22, 67, true},  {"CubeIllusionTri.asc", 10, 51, false},
    {"SRB.asc", 7, 73, true},          {"Turkey.asc", 11, 74, true},
    {"astryx-star.asc", 10, 57, true}, {"smallest-square.asc", 4, 16, false},
};

void PrintTo(const CorpusDesign& d, std::ostream* os) {
    *os << d.file;
}

double toDegrees(double r) {
    return r * 180 / kPi;
}
double toRadians(double d) {
    return d * kPi / 180;
}

// The outward normal GemCad gives a facet (docs/optics.md, "GemCad designs").
Vec3 fileNormal(double angleDeg, double azimuthDeg) {
    const double slope = toRadians(std::fabs(angleDeg)), phi = toRadians(azimuthDeg);
    const double up = std::signbit(angleDeg) ? -std::cos(slope) : std::cos(slope);
    return {std::sin(slope) * std::sin(phi), std::sin(slope) * std::cos(phi), up};
}

// A normal's signed slope from the girdle plane (negative below it) and its azimuth clockwise from +y.
double slopeDeg(const Vec3& n) {
    const double s = toDegrees(std::atan2(std::hypot(n.x, n.y), std::fabs(n.z)));
    return std::signbit(n.z) ? -s : s;
}
double azimuthDeg(const Vec3& n) {
    const double phi = toDegrees(std::atan2(n.x, n.y));
    return phi < 0 ? phi + 360 : phi;
}
double angleApart(double a, double b) {
    const double d = std::fmod(std::fabs(a - b), 360.0);
    return std::min(d, 360 - d);
}

std::string fileStem(const CorpusDesign& d) {
    std::string s = std::filesystem::path(d.file).stem().string();
    for (char& c : s)
        if (!std::isalnum(uint8_t(c))) c = '_';
    return s;
}

class GemCadCorpus : public testing::TestWithParam<CorpusDesign> {};

}  // namespace

TEST(GemCadCorpusTable, EveryCorpusDesignHasARow) {
    const auto files = test::corpusFiles(".asc");
    if (files.empty()) GTEST_SKIP() << "no designs in the corpus folder (tests/data/gemcad/SOURCES.md)";
    for (const auto& path : files) {
        bool found = false;
        for (const auto& row : kCorpus) found = found || path.filename() == row.file;
        EXPECT_TRUE(found) << path.filename() << " has no row in kCorpus";
    }
}

namespace {

// Opens a corpus file with loadStone and holds the stone to what the design's .asc states.
void expectAsTheFileStates(const std::filesystem::path& path, const test::AscFacts& facts,
                           const CorpusDesign& row) {
    const std::string file = path.filename().string();
    Stone stone;
    try {
        stone = loadStone(path.string());
    } catch (const Error& e) {
        FAIL() << file << " does not open: " << e.what();
    }
    EXPECT_EQ(stone.facets.size(), row.facets) << file << ": facets in the stone, against the file's";

    // Each facet the file lists has its own facet in the stone, at the tier's slope and the index's azimuth.
    std::set<size_t> used;
    size_t wrong = 0;
    std::ostringstream firstWrong;
    for (size_t t = 0; t < facts.tiers.size() && !stone.facets.empty(); ++t) {
        const test::AscTierFacts& tier = facts.tiers[t];
        for (double index : tier.indices) {
            const double azimuth = facts.azimuthDeg(index);
            const Vec3 want = fileNormal(tier.angleDeg, azimuth);
            size_t best = 0;
            for (size_t f = 1; f < stone.facets.size(); ++f)
                if (dot(stone.facets[f].normal, want) > dot(stone.facets[best].normal, want)) best = f;
            const Vec3 n = stone.facets[best].normal;
            const bool vertical = std::fabs(std::fabs(tier.angleDeg) - 90) < kToleranceDeg;
            const bool slopeOk = vertical ? std::fabs(std::fabs(slopeDeg(n)) - 90) <= kToleranceDeg
                                          : std::fabs(slopeDeg(n) - tier.angleDeg) <= kToleranceDeg;
            const bool level = std::fabs(tier.angleDeg) < kToleranceDeg;
            const bool azimuthOk = level || angleApart(azimuthDeg(n), azimuth) <= kToleranceDeg;
            if (slopeOk && azimuthOk && used.insert(best).second) continue;
            if (wrong++ == 0)
                firstWrong << "tier " << t + 1 << " (" << tier.angleDeg << " deg) index " << index
                           << ": nearest facet at " << slopeDeg(n) << " deg, azimuth " << azimuthDeg(n)
                           << ", want azimuth " << azimuth;
        }
    }
    EXPECT_EQ(wrong, 0u) << file << ": " << wrong << " of " << row.facets
                         << " facets not where the file puts them; first: " << firstWrong.str();

    if (row.table) {
        bool up = false;
        for (const Facet& f : stone.facets) up = up || f.normal.z >= std::cos(toRadians(kToleranceDeg));
        EXPECT_TRUE(up) << file << ": no facet faces +z: the table was turned away (tipped)";
    }
}

// The corpus file of this row with the given extension, and what its .asc states; empty if absent.
std::filesystem::path corpusFile(const CorpusDesign& row, const std::string& extension) {
    std::filesystem::path want = row.file;
    want.replace_extension(extension);
    for (const auto& p : test::corpusFiles(extension))
        if (p.filename() == want) return p;
    return {};
}

test::AscFacts checkedFacts(const CorpusDesign& row) {
    const test::AscFacts facts = test::readAscFacts(test::readWholeFile(corpusFile(row, ".asc")));
    EXPECT_EQ(facts.tiers.size(), row.tiers) << "the test's reading of " << row.file;
    EXPECT_EQ(facts.facetCount(), row.facets) << "the test's reading of " << row.file;
    return facts;
}

}  // namespace

TEST_P(GemCadCorpus, OpensAsTheFileStates) {
    const CorpusDesign& row = GetParam();
    const std::filesystem::path path = corpusFile(row, ".asc");
    if (path.empty()) GTEST_SKIP() << row.file << " is not in the corpus folder";
    expectAsTheFileStates(path, checkedFacts(row), row);
}

// The same design saved as GemCad's binary .gem opens as its .asc states.
TEST_P(GemCadCorpus, GemOpensAsItsAscStates) {
    const CorpusDesign& row = GetParam();
    const std::filesystem::path path = corpusFile(row, ".gem");
    if (path.empty() || corpusFile(row, ".asc").empty()) GTEST_SKIP() << "no .asc/.gem pair for " << row.file;
    expectAsTheFileStates(path, checkedFacts(row), row);
}

INSTANTIATE_TEST_SUITE_P(Corpus, GemCadCorpus, testing::ValuesIn(kCorpus),
                         [](const testing::TestParamInfo<CorpusDesign>& info) {
                             return fileStem(info.param);
                         });
