#include "cuts/step_cuts.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cuts/facet_design.h"
#include "util/error.h"

namespace facetlight {

namespace {

constexpr double kR = 0.5;

void check(bool ok, const std::string& input, double value, const std::string& why) {
    if (!ok) throw Error(input + " " + formatNumber(value) + ": " + why);
}

// One ring: a facet at each azimuth with the given slope, crossing height z at `reach(azimuth)` from the
// axis.
template <class Reach>
void addRing(std::vector<NamedPlane>& planes, const std::string& name, const std::vector<double>& azimuths,
             double slopeDeg, bool up, Reach reach, double z) {
    for (size_t j = 0; j < azimuths.size(); ++j)
        planes.push_back(facetPlane(name + "_" + std::to_string(j + 1), azimuths[j], slopeDeg, up,
                                    polar(reach(azimuths[j]), azimuths[j], z)));
}

void addGirdle(std::vector<NamedPlane>& planes, const std::vector<double>& azimuths,
               const std::vector<double>& reaches) {
    for (size_t j = 0; j < azimuths.size(); ++j) {
        const double az = radians(azimuths[j]);
        planes.push_back({{{std::cos(az), std::sin(az), 0}, reaches[j]}, "girdle_" + std::to_string(j + 1)});
    }
}

std::vector<double> evenAzimuths(int count, double startDeg) {
    std::vector<double> out;
    for (int j = 0; j < count; ++j) out.push_back(startDeg + 360.0 * j / count);
    return out;
}

}  // namespace

PolygonMesh makeStepCut(const StepCutParams& p) {
    check(p.ratio >= 1 && p.ratio <= 3, "ratio", p.ratio, "length / width must lie between 1 and 3");
    check(p.cornerPct > 0 && p.cornerPct < 50, "corner", p.cornerPct,
          "must lie between 0 and 50% of the width");
    check(p.tablePct > 0 && p.tablePct < 100, "table", p.tablePct,
          "must lie between 0 and 100% of the width");
    check(p.girdlePct >= 0 && p.girdlePct < 50, "girdle", p.girdlePct, "must be at least 0 and below 50%");
    check(p.crownSteps >= 1 && p.crownSteps <= 6, "crown steps", p.crownSteps, "must be 1 to 6");
    check(p.pavilionSteps >= 1 && p.pavilionSteps <= 6, "pavilion steps", p.pavilionSteps, "must be 1 to 6");
    const double innerCrown = p.crownAngleDeg - (p.crownSteps - 1) * p.crownStepDeg;
    const double innerPavilion = p.pavilionAngleDeg - (p.pavilionSteps - 1) * p.pavilionStepDeg;
    check(
        p.crownAngleDeg < 90 && innerCrown > 0, "crown angle", p.crownAngleDeg,
        "with the crown step, every crown step's slope must lie between 0 and 90 degrees (the innermost is " +
            formatNumber(innerCrown) + ")");
    check(p.pavilionAngleDeg < 90 && innerPavilion > 0, "pavilion angle", p.pavilionAngleDeg,
          "with the pavilion step, every pavilion step's slope must lie between 0 and 90 degrees (the "
          "innermost "
          "is " +
              formatNumber(innerPavilion) + ")");
    check(p.crownStepDeg >= 0, "crown step", p.crownStepDeg,
          "must not be negative (the stone must stay convex)");
    check(p.pavilionStepDeg >= 0, "pavilion step", p.pavilionStepDeg,
          "must not be negative (the stone must stay convex)");

    // The outline's edges face the 8 directions k * 45 deg; a corner cut k wide sits 45 deg off the sides.
    const double L = p.ratio, k = p.cornerPct / 100, h = p.girdlePct / 200;
    const std::vector<double> azimuths = evenAzimuths(8, 0);
    auto edge = [&](double az) {
        const int i = int(std::lround(az / 45)) % 8;
        if (i % 4 == 0) return L / 2;
        if (i % 4 == 2) return 0.5;
        return (L / 2 + 0.5 - k) / std::sqrt(2.0);
    };
    std::vector<NamedPlane> planes;
    // Crown steps of equal width from the girdle to the table edge; the table is table% of the width.
    const double crownWidth = 0.5 * (1 - p.tablePct / 100) / p.crownSteps;
    double z = h;
    for (int i = 0; i < p.crownSteps; ++i) {
        const double slope = p.crownAngleDeg - i * p.crownStepDeg;
        addRing(
            planes, "crown_step_" + std::to_string(i + 1), azimuths, slope, true,
            [&](double az) { return edge(az) - i * crownWidth; }, z);
        z += crownWidth * std::tan(radians(slope));
    }
    planes.insert(planes.begin(), {{{0, 0, 1}, z}, "table"});
    std::vector<double> reaches;
    for (double az : azimuths) reaches.push_back(edge(az));
    addGirdle(planes, azimuths, reaches);
    // Pavilion steps share out each direction's room down to the keel (the segment |x| <= (L - 1) / 2,
    // y = 0). The last step runs from the four sides into the keel; the corners' steps end above it.
    auto room = [&](double az) { return edge(az) - std::fabs(std::cos(radians(az))) * (L - 1) / 2; };
    for (int i = 0; i < p.pavilionSteps; ++i) {
        const double slope = p.pavilionAngleDeg - i * p.pavilionStepDeg;
        const bool last = i > 0 && i + 1 == p.pavilionSteps;
        for (size_t j = 0; j < azimuths.size(); ++j) {
            if (last && j % 2 == 1) continue;
            const double az = azimuths[j], width = room(az) / p.pavilionSteps;
            double zi = -h;
            for (int s = 0; s < i; ++s)
                zi -= width * std::tan(radians(p.pavilionAngleDeg - s * p.pavilionStepDeg));
            planes.push_back(
                facetPlane("pavilion_step_" + std::to_string(i + 1) + "_" + std::to_string(j + 1), az, slope,
                           false, polar(edge(az) - i * width, az, zi)));
        }
    }
    return intersectDesign(planes, "check the table, corner and step angles");
}

PolygonMesh makeSingleCut(const SingleCutParams& p) {
    check(p.tablePct > 0 && p.tablePct < 100, "table", p.tablePct, "must lie between 0 and 100%");
    check(p.crownAngleDeg > 0 && p.crownAngleDeg < 90, "crown angle", p.crownAngleDeg,
          "must lie between 0 and 90 degrees");
    check(p.pavilionAngleDeg > 0 && p.pavilionAngleDeg < 90, "pavilion angle", p.pavilionAngleDeg,
          "must lie between 0 and 90 degrees");
    check(p.girdlePct > 0 && p.girdlePct < 50, "girdle", p.girdlePct, "must lie between 0 and 50%");
    check(p.culetPct >= 0 && p.culetPct < 100, "culet", p.culetPct, "must be at least 0 and below 100%");
    check(p.girdleFacets >= 8 && p.girdleFacets <= 400 && p.girdleFacets % 8 == 0, "girdle facets",
          p.girdleFacets, "must be a multiple of 8 from 8 to 400, so that a girdle facet faces every main");
    const double h = p.girdlePct / 200, C = radians(p.crownAngleDeg), P = radians(p.pavilionAngleDeg);
    const auto mains = evenAzimuths(8, 0);
    auto girdleReach = [](double) { return kR; };
    // The table's corners lie between the mains, at table% / 2 from the axis.
    const double tableZ = h + (kR - p.tablePct / 200 * std::cos(radians(22.5))) * std::tan(C);
    std::vector<NamedPlane> planes{{{{0, 0, 1}, tableZ}, "table"}};
    addRing(planes, "crown_main", mains, p.crownAngleDeg, true, girdleReach, h);
    const auto girdle = evenAzimuths(p.girdleFacets, 0);
    addGirdle(planes, girdle, std::vector<double>(girdle.size(), kR));
    addRing(planes, "pavilion_main", mains, p.pavilionAngleDeg, false, girdleReach, -h);
    if (p.culetPct > 0) planes.push_back({{{0, 0, -1}, h + (kR - p.culetPct / 200) * std::tan(P)}, "culet"});
    return intersectDesign(planes, "check the table against the crown angle");
}

PolygonMesh makeRoseCut(const RoseCutParams& p) {
    check(p.girdlePct > 0 && p.girdlePct < 50, "girdle", p.girdlePct, "must lie between 0 and 50%");
    check(p.girdleFacets >= 12 && p.girdleFacets <= 396 && p.girdleFacets % 12 == 0, "girdle facets",
          p.girdleFacets, "must be a multiple of 12 from 12 to 396");
    check(p.lowerAngleDeg < 90 && p.middleAngleDeg < p.lowerAngleDeg, "middle angle", p.middleAngleDeg,
          "must be flatter than the lower angle (" + formatNumber(p.lowerAngleDeg) +
              "), which must be below 90");
    check(p.topAngleDeg > 0 && p.topAngleDeg < p.middleAngleDeg, "top angle", p.topAngleDeg,
          "must be positive and flatter than the middle angle (" + formatNumber(p.middleAngleDeg) + ")");
    const double h = p.girdlePct / 200;
    // The rings' lower edges cross the axis-facing profile at these radii (fractions of the girdle radius).
    const double rMiddle = 0.62 * kR, rTop = 0.34 * kR;
    std::vector<NamedPlane> planes;
    double z = h;
    addRing(
        planes, "lower", evenAzimuths(12, 15), p.lowerAngleDeg, true, [](double) { return kR; }, z);
    z += (kR - rMiddle) * std::tan(radians(p.lowerAngleDeg));
    addRing(
        planes, "middle", evenAzimuths(6, 0), p.middleAngleDeg, true, [&](double) { return rMiddle; }, z);
    z += (rMiddle - rTop) * std::tan(radians(p.middleAngleDeg));
    addRing(
        planes, "top", evenAzimuths(6, 30), p.topAngleDeg, true, [&](double) { return rTop; }, z);
    const auto girdle = evenAzimuths(p.girdleFacets, 0);
    addGirdle(planes, girdle, std::vector<double>(girdle.size(), kR));
    planes.push_back({{{0, 0, -1}, h}, "base"});
    return intersectDesign(planes, "check that the angles flatten from the girdle to the top");
}

}  // namespace facetlight
