#include "cuts/round_brilliant.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cuts/facet_design.h"
#include "util/error.h"

namespace facetlight {

namespace {

constexpr double kR = 0.5;  // girdle radius: the diameter is the unit of every percentage

void check(bool ok, const std::string& input, double value, const std::string& why) {
    if (!ok) throw Error(input + " " + formatNumber(value) + ": " + why);
}

void validate(const RoundBrilliantParams& p) {
    const double n = p.girdleFacets;
    check(p.tablePct > 0 && p.tablePct<100, "table", p.tablePct, p.tablePct> 0
              ? "a table this wide swallows the crown; it must be less than 100%"
              : "must be positive");
    check(p.crownAngleDeg > 0 && p.crownAngleDeg < 90, "crown angle", p.crownAngleDeg,
          "must lie between 0 and 90 degrees");
    check(p.pavilionAngleDeg > 0 && p.pavilionAngleDeg < 90, "pavilion angle", p.pavilionAngleDeg,
          "must lie between 0 and 90 degrees");
    check(p.girdlePct >= 0 && p.girdlePct < 50, "girdle", p.girdlePct, "must be at least 0 and below 50%");
    check(p.starPct > 0 && p.starPct<100, "star", p.starPct, p.starPct> 0
              ? "stars this long reach the girdle and leave no room for the upper halves; it must be "
                "less than 100%"
              : "must be positive");
    check(p.lowerHalfPct > 0 && p.lowerHalfPct<100, "lower half", p.lowerHalfPct, p.lowerHalfPct> 0
              ? "lower halves this long reach the culet point; it must be less than 100%"
              : "must be positive");
    check(p.culetPct >= 0 && p.culetPct < 100, "culet", p.culetPct, "must be at least 0 and below 100%");
    check(p.girdleFacets == 0 || (p.girdleFacets % 16 == 0 && p.girdleFacets >= 16 && p.girdleFacets <= 400),
          "girdle facets", n,
          "use 0 (smooth) or a multiple of 16 from 16 to 400, so that a girdle facet faces "
          "every main and every star");
    // The lower halves meet on the pavilion ridges; the culet's corners sit on the same ridges.
    const double ridgeToCulet = 100 * (1 - p.culetPct / 100 / std::cos(radians(22.5)));
    check(p.lowerHalfPct < ridgeToCulet, "lower half", p.lowerHalfPct,
          "lower halves this long run into the culet (culet " + formatNumber(p.culetPct) + "%); at most " +
              formatNumber(std::floor(ridgeToCulet * 100) / 100) + "% fits");
}

// The azimuth of the upper and lower halves from the main they flank. Trade: the chord from the main's girdle
// point to the 22.5-deg girdle point is horizontal, so the half faces 11.25 deg off the main. Faceter: 3.75
// deg (index 1 on a 96 gear, as in the usual brilliant diagram), narrowed for fine girdles so that the girdle
// stays thinnest near the mains; on a knife edge the halves meet the girdle in the 16-gon's chords.
double halfAzimuthDeg(const RoundBrilliantParams& p, int sides) {
    if (p.halves == HalvesLayout::Trade || p.girdlePct == 0) return 11.25;
    return std::min(3.75, 2.0 / 3.0 * 360.0 / sides);
}

// How far outside the line through a half's girdle point, across the half's azimuth (`a` deg off the main),
// the girdle polygon reaches: a half of slope s comes tan(s) times this much closer to the girdle plane there,
// where the girdle is thinnest. The polygon's sides lie at distance kR, its corners at 360 (k + 1/2) / sides.
double girdleBulge(int sides, double a) {
    if (sides == 0) return 0;  // knife edge: the outline is the halves' own chords
    double reach = 0;
    for (int k = 0; k < sides; ++k)
        reach = std::max(reach, std::cos(radians(360.0 * (k + 0.5) / sides - a)));
    return kR * (reach / std::cos(radians(180.0 / sides)) - std::cos(radians(a)));
}

}  // namespace

int girdleSideCount(const RoundBrilliantParams& p) {
    if (p.girdlePct == 0) return 0;
    return p.girdleFacets == 0 ? 64 : p.girdleFacets;
}

namespace {

// The slopes of the halves and the heights of the girdle's rims where the mains meet it.
struct Tiers {
    double halfAzimuthDeg, tableEdge, starR, starDrop, tanUpper, tanLower;
    GirdleRims rims;
};

Tiers tiersOf(const RoundBrilliantParams& p) {
    validate(p);
    Tiers t;
    const double T = p.tablePct / 100;
    const double tanC = std::tan(radians(p.crownAngleDeg)), tanP = std::tan(radians(p.pavilionAngleDeg));
    const int sides = girdleSideCount(p);
    const double a = t.halfAzimuthDeg = halfAzimuthDeg(p, sides);
    const double cos225 = std::cos(radians(22.5)), cosA = std::cos(radians(a));
    const double cosRest = std::cos(radians(22.5 - a));
    // Star tip: on the ridge between two bezels, star % of the way from the table edge to the girdle; it lies
    // tanC (kR - starR cos 22.5) above the bezels' girdle points. The lower-half point: on the ridge between
    // two mains, lower-half % of the way from the girdle to the centre, as far below the mains' girdle points.
    t.tableEdge = T / 2 * cos225;
    t.starR = t.tableEdge + p.starPct / 100 * (kR - t.tableEdge);
    t.starDrop = tanC * (kR - t.starR * cos225);
    const double lowerR = kR * (1 - p.lowerHalfPct / 100);
    const double lowerRise = tanP * (kR - lowerR * cos225);
    // Each half runs through its main's girdle point and the star tip (lower-half point).
    t.tanUpper = t.starDrop / (kR * cosA - t.starR * cosRest);
    t.tanLower = lowerRise / (kR * cosA - lowerR * cosRest);
    // The rims sit so that the girdle is girdle % thick where the halves bring them closest together.
    const double bulge = girdleBulge(sides, a);
    t.rims = {p.girdlePct / 200 + t.tanUpper * bulge, -(p.girdlePct / 200 + t.tanLower * bulge)};
    return t;
}

}  // namespace

GirdleRims girdleRims(const RoundBrilliantParams& params) { return tiersOf(params).rims; }

std::vector<NamedPlane> roundBrilliantPlanes(const RoundBrilliantParams& p) {
    const Tiers t = tiersOf(p);
    const double T = p.tablePct / 100, c = p.culetPct / 100;
    const double tanC = std::tan(radians(p.crownAngleDeg)), tanP = std::tan(radians(p.pavilionAngleDeg));
    const int sides = girdleSideCount(p);
    const double a = t.halfAzimuthDeg, tanUpper = t.tanUpper, tanLower = t.tanLower;
    const double upperRim = t.rims.upper, lowerRim = t.rims.lower;
    const double tableEdge = t.tableEdge, starR = t.starR;

    const double tableZ = upperRim + (kR - T / 2) * tanC;
    const double starZ = upperRim + t.starDrop;
    const double starSlope = degrees(std::atan((tableZ - starZ) / (starR - tableEdge)));

    std::vector<NamedPlane> planes;
    planes.push_back({{{0, 0, 1}, tableZ}, "table"});
    for (int k = 0; k < 8; ++k) {
        const double az = 22.5 + 45 * k;
        planes.push_back(
            facetPlane("star_" + std::to_string(k + 1), az, starSlope, true, polar(starR, az, starZ)));
    }
    for (int k = 0; k < 8; ++k)
        planes.push_back(facetPlane("bezel_" + std::to_string(k + 1), 45 * k, p.crownAngleDeg, true,
                                    polar(kR, 45 * k, upperRim)));
    // upper_half_1 is at +a from bezel_1, upper_half_2 at -a from bezel_2, and so on; the lower halves alike.
    auto halfAzimuth = [a](int k) { return 45 * ((k + 1) / 2 % 8) + (k % 2 == 0 ? a : -a); };
    auto mainOf = [](int k) { return 45.0 * ((k + 1) / 2 % 8); };
    for (int k = 0; k < 16; ++k)
        planes.push_back(facetPlane("upper_half_" + std::to_string(k + 1), halfAzimuth(k),
                                    degrees(std::atan(tanUpper)), true, polar(kR, mainOf(k), upperRim)));
    for (int k = 0; k < sides; ++k) {
        const double az = radians(360.0 * k / sides);
        planes.push_back({{{std::cos(az), std::sin(az), 0}, kR}, "girdle_" + std::to_string(k + 1)});
    }
    for (int k = 0; k < 8; ++k)
        planes.push_back(facetPlane("pavilion_main_" + std::to_string(k + 1), 45 * k, p.pavilionAngleDeg,
                                    false, polar(kR, 45 * k, lowerRim)));
    for (int k = 0; k < 16; ++k)
        planes.push_back(facetPlane("lower_half_" + std::to_string(k + 1), halfAzimuth(k),
                                    degrees(std::atan(tanLower)), false, polar(kR, mainOf(k), lowerRim)));
    if (c > 0) planes.push_back({{{0, 0, -1}, -lowerRim + (kR - c / 2) * tanP}, "culet"});
    return planes;
}

PolygonMesh makeRoundBrilliant(const RoundBrilliantParams& params) {
    return intersectDesign(roundBrilliantPlanes(params),
                           "check the star and lower-half lengths against the table, angles and culet");
}

}  // namespace facetlight
