#pragma once
// Cuts made of rings of facets around an outline, each ring one slope: step cuts (emerald, Asscher), the
// single cut and the rose cut. Rings are laid on a convex profile, so every ring shows.
#include "geometry/polygon_mesh.h"

namespace facetlight {

// A rectangle (or square) with cut corners, three crown and three pavilion steps ending in a keel.
struct StepCutParams {
    double ratio = 1.4;            // length / width
    double cornerPct = 15;         // corner cut, % of the width
    double tablePct = 62;          // table width, % of the width
    double crownAngleDeg = 42;     // the step at the girdle; each step inward is flatter
    double pavilionAngleDeg = 50;  // the step at the girdle; each step inward is flatter
    double girdlePct = 2;
    double crownStepDeg = 8;  // how much flatter each crown step is than the one outside it
    double pavilionStepDeg = 6;
    int crownSteps = 3;
    int pavilionSteps = 3;
};
PolygonMesh makeStepCut(const StepCutParams& params);

// Table, 8 crown and 8 pavilion facets on a round girdle: the oldest brilliant, used for small stones.
struct SingleCutParams {
    double tablePct = 55;  // corner to corner
    double crownAngleDeg = 35;
    double pavilionAngleDeg = 41;
    double girdlePct = 2;
    double culetPct = 0;
    int girdleFacets = 32;  // a multiple of 8
};
PolygonMesh makeSingleCut(const SingleCutParams& params);

// A flat base under a dome of triangles: 12 lower, 6 middle and 6 top facets meeting in a point (the
// Dutch rose, 24 facets).
struct RoseCutParams {
    double lowerAngleDeg = 55;
    double middleAngleDeg = 35;
    double topAngleDeg = 18;
    double girdlePct = 2;
    int girdleFacets = 24;  // a multiple of 12
};
PolygonMesh makeRoseCut(const RoseCutParams& params);

}  // namespace facetlight
