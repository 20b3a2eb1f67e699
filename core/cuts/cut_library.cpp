#include "cuts/cut_library.h"

#include <cmath>

#include "cuts/facet_design.h"
#include "cuts/fancy_cuts.h"
#include "cuts/round_brilliant.h"
#include "cuts/step_cuts.h"
#include "util/error.h"

namespace facetlight {

namespace {

using Params = std::vector<CutParameter>;

std::string choiceList(const CutParameter& param) {
    std::string out;
    for (const auto& c : param.choices) out += (out.empty() ? "" : ", ") + c;
    return out;
}

// The round brilliant's tiers, with defaults from `d`; fancy shapes and presets share them.
Params brilliantParameters(const RoundBrilliantParams& d) {
    return {
        {"table", "%", "table, corner to corner (fancy shapes: across the width)", d.tablePct, 20, 90},
        {"crown", "deg", "crown angle (bezels)", d.crownAngleDeg, 10, 60},
        {"pavilion", "deg", "pavilion angle (mains)", d.pavilionAngleDeg, 20, 60},
        {"girdle", "%", "girdle thickness where thinnest (the middle of each half); 0 = knife edge", d.girdlePct,
         0, 10},
        {"star", "%", "star length, table edge to girdle", d.starPct, 10, 90},
        {"lower_half", "%", "lower-half length, girdle to centre", d.lowerHalfPct, 10, 95},
        {"culet", "%", "culet, flat to flat; 0 = pointed", d.culetPct, 0, 30},
        {"girdle_facets", "", "0 = smooth (64 sides), else a multiple of 16", double(d.girdleFacets), 0, 400,
         true},
    };
}

// Round outlines only: the fancy shapes keep the faceters' halves, which stay in place when their planes are
// laid on a pointed outline (the trade's construction is defined on the circle).
Params roundParameters(const RoundBrilliantParams& d) {
    Params params = brilliantParameters(d);
    params.push_back({"halves", "",
                      "trade: the trade's halves (DiamCalc, GIA reports); faceter: 3.75 deg off the mains, "
                      "another stone",
                      double(d.halves), 0, 1, true, {"trade", "faceter"}});
    return params;
}

RoundBrilliantParams brilliantValues(const CutValues& v) {
    RoundBrilliantParams p;
    p.tablePct = v.at("table");
    p.crownAngleDeg = v.at("crown");
    p.pavilionAngleDeg = v.at("pavilion");
    p.girdlePct = v.at("girdle");
    p.starPct = v.at("star");
    p.lowerHalfPct = v.at("lower_half");
    p.culetPct = v.at("culet");
    p.girdleFacets = int(v.at("girdle_facets"));
    p.halves = v.count("halves") ? HalvesLayout(int(v.at("halves"))) : HalvesLayout::Faceter;
    return p;
}

RoundBrilliantParams withValues(double table, double crown, double pavilion, double girdle, double star,
                                double lowerHalf, double culet) {
    RoundBrilliantParams p;
    p.tablePct = table, p.crownAngleDeg = crown, p.pavilionAngleDeg = pavilion, p.girdlePct = girdle;
    p.starPct = star, p.lowerHalfPct = lowerHalf, p.culetPct = culet;
    return p;
}

CutShape roundShape(std::string name, std::string description, const RoundBrilliantParams& defaults) {
    return {std::move(name), std::move(description), roundParameters(defaults),
            [](const CutValues& v) { return makeRoundBrilliant(brilliantValues(v)); }};
}

CutShape fancyShape(std::string name, std::string description, FancyOutline outline, double ratio,
                    const RoundBrilliantParams& tiers, double corner = 0) {
    Params params = brilliantParameters(tiers);
    params.push_back({"ratio", "", "length / width", ratio, 1, 3});
    if (corner > 0)
        params.push_back({"corner", "%",
                          outline == FancyOutline::Cushion ? "corner radius, % of the width"
                                                           : "corner cut, % of the width",
                          corner, 1, 45});
    return {std::move(name), std::move(description), std::move(params), [outline](const CutValues& v) {
                FancyBrilliantParams p;
                p.outline = outline;
                p.tiers = brilliantValues(v);
                p.ratio = v.at("ratio");
                if (v.count("corner")) p.cornerPct = v.at("corner");
                return makeFancyBrilliant(p);
            }};
}

CutShape stepShape(std::string name, std::string description, const StepCutParams& d) {
    Params params{
        {"ratio", "", "length / width", d.ratio, 1, 3},
        {"corner", "%", "corner cut, % of the width", d.cornerPct, 1, 45},
        {"table", "%", "table, % of the width", d.tablePct, 20, 90},
        {"crown", "deg", "crown angle of the step at the girdle", d.crownAngleDeg, 10, 70},
        {"pavilion", "deg", "pavilion angle of the step at the girdle", d.pavilionAngleDeg, 20, 80},
        {"girdle", "%", "girdle thickness", d.girdlePct, 0, 10},
        {"crown_step", "deg", "each crown step is this much flatter than the one outside it", d.crownStepDeg,
         0, 20},
        {"pavilion_step", "deg", "each pavilion step is this much flatter than the one outside it",
         d.pavilionStepDeg, 0, 20},
        {"crown_steps", "", "number of crown steps", double(d.crownSteps), 1, 6, true},
        {"pavilion_steps", "", "number of pavilion steps", double(d.pavilionSteps), 1, 6, true},
    };
    return {std::move(name), std::move(description), std::move(params), [](const CutValues& v) {
                StepCutParams p;
                p.ratio = v.at("ratio"), p.cornerPct = v.at("corner"), p.tablePct = v.at("table");
                p.crownAngleDeg = v.at("crown"), p.pavilionAngleDeg = v.at("pavilion"),
                p.girdlePct = v.at("girdle");
                p.crownStepDeg = v.at("crown_step"), p.pavilionStepDeg = v.at("pavilion_step");
                p.crownSteps = int(v.at("crown_steps")), p.pavilionSteps = int(v.at("pavilion_steps"));
                return makeStepCut(p);
            }};
}

std::vector<CutShape> buildLibrary() {
    const RoundBrilliantParams gia;  // the defaults are the GIA reference stone
    std::vector<CutShape> shapes;
    shapes.push_back(roundShape("round_brilliant", "round brilliant, GIA reference proportions", gia));
    RoundBrilliantParams tolkowsky = withValues(53, 34.5, 40.75, 0, 50, 75, 0);
    shapes.push_back(
        roundShape("round_brilliant_tolkowsky", "Tolkowsky's 1919 brilliant, knife-edge girdle", tolkowsky));
    RoundBrilliantParams deep = gia, shallow = gia;
    deep.pavilionAngleDeg = 43.0;
    shallow.pavilionAngleDeg = 38.5;
    shapes.push_back(
        roundShape("round_brilliant_deep", "round brilliant with a deep pavilion (nail-head)", deep));
    shapes.push_back(
        roundShape("round_brilliant_shallow", "round brilliant with a shallow pavilion (fish-eye)", shallow));
    shapes.push_back(roundShape("old_european", "old European cut: small table, high crown, open culet",
                                withValues(42, 40, 41.5, 1.5, 55, 55, 12)));
    shapes.push_back(fancyShape("oval", "oval brilliant", FancyOutline::Oval, 1.4, gia));
    shapes.push_back(fancyShape("pear", "pear brilliant", FancyOutline::Pear, 1.5, gia));
    shapes.push_back(fancyShape("marquise", "marquise brilliant", FancyOutline::Marquise, 2.0, gia));
    shapes.push_back(fancyShape("heart", "heart brilliant (convex: the cleft is filled in)",
                                FancyOutline::Heart, 1.1, gia));
    shapes.push_back(
        fancyShape("cushion", "cushion brilliant: rounded square", FancyOutline::Cushion, 1.0, gia, 25));
    RoundBrilliantParams princess = gia;
    princess.tablePct = 68;
    shapes.push_back(fancyShape("princess", "princess: square brilliant with pointed corners",
                                FancyOutline::Princess, 1.0, princess));
    RoundBrilliantParams radiant = gia;
    radiant.tablePct = 64;
    shapes.push_back(fancyShape("radiant", "radiant: cut-cornered rectangular brilliant",
                                FancyOutline::Radiant, 1.2, radiant, 15));
    shapes.push_back(stepShape("emerald", "emerald step cut", StepCutParams{}));
    StepCutParams asscher;
    asscher.ratio = 1.0, asscher.cornerPct = 25, asscher.tablePct = 55, asscher.crownAngleDeg = 40;
    shapes.push_back(stepShape("asscher", "Asscher: square step cut with wide corners", asscher));
    const SingleCutParams single;
    shapes.push_back(
        {"single_cut",
         "single cut: table, 8 crown and 8 pavilion facets",
         {{"table", "%", "table, corner to corner", single.tablePct, 20, 90},
          {"crown", "deg", "crown angle", single.crownAngleDeg, 10, 60},
          {"pavilion", "deg", "pavilion angle", single.pavilionAngleDeg, 20, 60},
          {"girdle", "%", "girdle thickness", single.girdlePct, 0.1, 10},
          {"culet", "%", "culet, flat to flat; 0 = pointed", single.culetPct, 0, 30},
          {"girdle_facets", "", "girdle sides, a multiple of 8", double(single.girdleFacets), 8, 400, true}},
         [](const CutValues& v) {
             SingleCutParams p;
             p.tablePct = v.at("table"), p.crownAngleDeg = v.at("crown");
             p.pavilionAngleDeg = v.at("pavilion"), p.girdlePct = v.at("girdle");
             p.culetPct = v.at("culet"), p.girdleFacets = int(v.at("girdle_facets"));
             return makeSingleCut(p);
         }});
    const RoseCutParams rose;
    shapes.push_back(
        {"rose_cut",
         "Dutch rose: a dome of 24 triangles on a flat base",
         {{"lower", "deg", "slope of the 12 facets at the girdle", rose.lowerAngleDeg, 10, 80},
          {"middle", "deg", "slope of the 6 middle facets", rose.middleAngleDeg, 5, 75},
          {"top", "deg", "slope of the 6 facets meeting at the top", rose.topAngleDeg, 2, 70},
          {"girdle", "%", "girdle thickness", rose.girdlePct, 0.1, 10},
          {"girdle_facets", "", "girdle sides, a multiple of 12", double(rose.girdleFacets), 12, 396, true}},
         [](const CutValues& v) {
             RoseCutParams p;
             p.lowerAngleDeg = v.at("lower"), p.middleAngleDeg = v.at("middle");
             p.topAngleDeg = v.at("top"), p.girdlePct = v.at("girdle");
             p.girdleFacets = int(v.at("girdle_facets"));
             return makeRoseCut(p);
         }});
    return shapes;
}

}  // namespace

double choiceIndex(const CutParameter& param, const std::string& name) {
    for (size_t i = 0; i < param.choices.size(); ++i)
        if (param.choices[i] == name) return double(i);
    throw Error(param.name + " '" + name + "': must be one of " + choiceList(param));
}

std::string parameterText(const CutParameter& param, double value) {
    if (!param.choices.empty() && value >= 0 && value < double(param.choices.size()))
        return param.choices[size_t(value)];
    return formatNumber(value);
}

const std::vector<CutShape>& cutShapes() {
    static const std::vector<CutShape> shapes = buildLibrary();
    return shapes;
}

std::string knownShapeNames() {
    std::string out;
    for (const auto& s : cutShapes()) out += (out.empty() ? "" : ", ") + s.name;
    return out;
}

const CutShape& findCutShape(const std::string& name) {
    for (const auto& s : cutShapes())
        if (s.name == name) return s;
    throw Error("unknown shape '" + name + "'; the shapes are: " + knownShapeNames());
}

CutValues completeCutValues(const CutShape& shape, const CutValues& values) {
    CutValues out;
    for (const auto& p : shape.parameters) out[p.name] = p.defaultValue;
    for (const auto& [name, value] : values) {
        const CutParameter* param = nullptr;
        for (const auto& p : shape.parameters)
            if (p.name == name) param = &p;
        if (!param) {
            std::string names;
            for (const auto& p : shape.parameters) names += (names.empty() ? "" : ", ") + p.name;
            throw Error(shape.name + " has no parameter '" + name + "'; its parameters are: " + names);
        }
        const std::string unit = param->unit == "%" ? "%" : param->unit.empty() ? "" : " " + param->unit;
        if (!std::isfinite(value) || value < param->min || value > param->max)
            throw Error(name + " " + formatNumber(value) + ": must lie between " + formatNumber(param->min) +
                        " and " + formatNumber(param->max) + unit);
        if (param->integer && value != std::floor(value))
            throw Error(name + " " + formatNumber(value) + ": must be a whole number");
        if (!param->choices.empty() && !(value >= 0 && value < double(param->choices.size())))
            throw Error(name + " " + formatNumber(value) + ": must be the index of one of " +
                        choiceList(*param));
        out[name] = value;
    }
    return out;
}

PolygonMesh makeCut(const std::string& shape, const CutValues& values) {
    const CutShape& s = findCutShape(shape);
    return s.build(completeCutValues(s, values));
}

std::string cutCommandLine(const CutShape& shape, const CutValues& completeValues) {
    std::string out = shape.name;
    for (const auto& p : shape.parameters) {
        std::string flag = p.name;
        for (char& c : flag)
            if (c == '_') c = '-';
        out += " --" + flag + " " + parameterText(p, completeValues.at(p.name));
    }
    return out;
}

}  // namespace facetlight
