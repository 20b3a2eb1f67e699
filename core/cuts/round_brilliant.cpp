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

// The azimuth of the upper and lower halves from the main they flank: 3.75 deg (index 1 on a 96 gear, as in
// the usual brilliant diagram), narrowed for fine girdles so that the girdle stays thinnest at the mains.
double halfAzimuthDeg(const RoundBrilliantParams& p, int sides) {
    if (p.girdlePct == 0) return 11.25;  // knife edge: the halves meet the girdle in the 16-gon's chords
    return std::min(3.75, 2.0 / 3.0 * 360.0 / sides);
}

}  // namespace

int girdleSideCount(const RoundBrilliantParams& p) {
    if (p.girdlePct == 0) return 0;
    return p.girdleFacets == 0 ? 64 : p.girdleFacets;
}

std::vector<NamedPlane> roundBrilliantPlanes(const RoundBrilliantParams& p) {
    validate(p);
    const double T = p.tablePct / 100, h = p.girdlePct / 200, c = p.culetPct / 100;
    const double C = radians(p.crownAngleDeg), P = radians(p.pavilionAngleDeg);
    const int sides = girdleSideCount(p);
    const double a = halfAzimuthDeg(p, sides);
    const double cos225 = std::cos(radians(22.5));

    const double tableZ = h + (kR - T / 2) * std::tan(C);
    // Star tip: on the ridge between two bezels, star % of the way from the table edge to the girdle.
    const double tableEdge = T / 2 * cos225;
    const double starR = tableEdge + p.starPct / 100 * (kR - tableEdge);
    const double starZ = h + std::tan(C) * (kR - starR * cos225);
    const double starSlope = degrees(std::atan((tableZ - starZ) / (starR - tableEdge)));
    const double upperSlope =
        degrees(std::atan((starZ - h) / (kR * std::cos(radians(a)) - starR * std::cos(radians(22.5 - a)))));
    // Lower-half point: on the ridge between two mains, lower-half % of the way from the girdle to the
    // centre.
    const double lowerR = kR * (1 - p.lowerHalfPct / 100);
    const double lowerZ = -h - std::tan(P) * (kR - lowerR * cos225);
    const double lowerSlope = degrees(
        std::atan((-h - lowerZ) / (kR * std::cos(radians(a)) - lowerR * std::cos(radians(22.5 - a)))));

    std::vector<NamedPlane> planes;
    planes.push_back({{{0, 0, 1}, tableZ}, "table"});
    for (int k = 0; k < 8; ++k) {
        const double az = 22.5 + 45 * k;
        planes.push_back(
            facetPlane("star_" + std::to_string(k + 1), az, starSlope, true, polar(starR, az, starZ)));
    }
    for (int k = 0; k < 8; ++k)
        planes.push_back(facetPlane("bezel_" + std::to_string(k + 1), 45 * k, p.crownAngleDeg, true,
                                    polar(kR, 45 * k, h)));
    for (int k = 0; k < 16; ++k) {
        const int main =
            (k + 1) / 2 % 8;  // upper_half_1 is at +a from bezel_1, upper_half_2 at -a from bezel_2
        const double az = 45 * main + (k % 2 == 0 ? a : -a);
        planes.push_back(
            facetPlane("upper_half_" + std::to_string(k + 1), az, upperSlope, true, polar(kR, 45 * main, h)));
    }
    for (int k = 0; k < sides; ++k) {
        const double az = radians(360.0 * k / sides);
        planes.push_back({{{std::cos(az), std::sin(az), 0}, kR}, "girdle_" + std::to_string(k + 1)});
    }
    for (int k = 0; k < 8; ++k)
        planes.push_back(facetPlane("pavilion_main_" + std::to_string(k + 1), 45 * k, p.pavilionAngleDeg,
                                    false, polar(kR, 45 * k, -h)));
    for (int k = 0; k < 16; ++k) {
        const int main = (k + 1) / 2 % 8;
        const double az = 45 * main + (k % 2 == 0 ? a : -a);
        planes.push_back(facetPlane("lower_half_" + std::to_string(k + 1), az, lowerSlope, false,
                                    polar(kR, 45 * main, -h)));
    }
    if (c > 0) planes.push_back({{{0, 0, -1}, h + (kR - c / 2) * std::tan(P)}, "culet"});
    return planes;
}

PolygonMesh makeRoundBrilliant(const RoundBrilliantParams& params) {
    return intersectDesign(roundBrilliantPlanes(params),
                           "check the star and lower-half lengths against the table, angles and culet");
}

}  // namespace facetlight
