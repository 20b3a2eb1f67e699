#include "cuts/cut_library.h"

#include <algorithm>
#include <cmath>

#include "cuts/facet_design.h"
#include "cuts/fancy_cuts.h"
#include "cuts/round_brilliant.h"
#include "cuts/step_cuts.h"
#include "settings/settings_schema.h"
#include "util/closest_name.h"
#include "util/error.h"
#include "util/excerpt.h"

namespace facetlight {

namespace {

using settings::Field;

std::string choiceList(const CutParameter& param) {
    std::string out;
    for (const auto& c : param.choices) out += (out.empty() ? "" : ", ") + c;
    return out;
}

// A design's parameters are the rows of a settings table over its params struct (settings/settings_schema.h):
// each row names the member it sets, its range, help and unit (the flag is --key with '-' for '_'). The
// parameters' list, defaults and checks, and the build, all follow from the rows.
settings::Doc about(std::string help, std::string unit = "") {
    return {"", std::move(help), std::move(unit)};
}

// The parameter a row describes, with the default the design's defaults give it (`value`, as the row writes
// it); a choice's value is the index of its name.
CutParameter cutParameter(const settings::FieldInfo& field, const nlohmann::json& value) {
    CutParameter p{field.key, field.doc.unit, field.doc.help};
    p.integer = field.type != settings::FieldType::Number;
    if (field.type == settings::FieldType::Number) {
        p.min = field.range.lo, p.max = field.range.hi, p.defaultValue = value.get<double>();
    } else if (field.type == settings::FieldType::Integer) {
        p.min = double(field.minCount), p.max = double(field.maxCount), p.defaultValue = value.get<double>();
    } else {
        p.choices = field.choices;
        p.min = 0, p.max = double(field.choices.size() - 1);
        p.defaultValue = choiceIndex(p, value.get<std::string>());
    }
    return p;
}

// Checked values as the rows read them: numbers, and a choice's name for its index.
nlohmann::json rowValues(const std::vector<CutParameter>& parameters, const CutValues& values) {
    nlohmann::json j = nlohmann::json::object();
    for (const CutParameter& p : parameters) {
        const double v = values.at(p.name);
        j[p.name] = p.choices.empty() ? nlohmann::json(v) : nlohmann::json(p.choices[size_t(v)]);
    }
    return j;
}

// A shape of the library: its design's defaults, the rows of its parameters, and what makes the mesh.
template <class P>
CutShape tableShape(std::string name, std::string description, const P& defaults, std::vector<Field<P>> rows,
                    PolygonMesh (*make)(const P&)) {
    const settings::Schema<P> schema(std::move(rows));
    const nlohmann::json given = schema.write(defaults);
    std::vector<CutParameter> parameters;
    for (const settings::FieldInfo& field : schema.fields())
        parameters.push_back(cutParameter(field, given.at(field.key)));
    return {std::move(name), std::move(description), parameters,
            [schema, defaults, parameters, make](const CutValues& v) {
                P p = defaults;
                schema.read(p, rowValues(parameters, v));
                return make(p);
            }};
}

// The round brilliant's tiers; fancy shapes and presets share them.
std::vector<Field<RoundBrilliantParams>> brilliantRows() {
    using P = RoundBrilliantParams;
    return {
        settings::number("table", &P::tablePct, {20, 90},
                         about("table, corner to corner (fancy shapes: across the width)", "%")),
        settings::number("crown", &P::crownAngleDeg, {10, 60}, about("crown angle (bezels)", "deg")),
        settings::number("pavilion", &P::pavilionAngleDeg, {20, 60}, about("pavilion angle (mains)", "deg")),
        settings::number(
            "girdle", &P::girdlePct, {0, 10},
            about("girdle thickness where thinnest (the middle of each half); 0 = knife edge", "%")),
        settings::number("star", &P::starPct, {10, 90}, about("star length, table edge to girdle", "%")),
        settings::number("lower_half", &P::lowerHalfPct, {10, 95},
                         about("lower-half length, girdle to centre", "%")),
        settings::number("culet", &P::culetPct, {0, 30}, about("culet, flat to flat; 0 = pointed", "%")),
        settings::count("girdle_facets", &P::girdleFacets, 0, 400,
                        about("0 = smooth (64 sides), else a multiple of 16")),
    };
}

// A row of the tiers as a row of a fancy shape, which holds them.
Field<FancyBrilliantParams> ofTiers(Field<RoundBrilliantParams> row) {
    return {row.info,
            [read = row.read](FancyBrilliantParams& p, const nlohmann::json& j, const std::string& path) {
                read(p.tiers, j, path);
            },
            [write = row.write](const FancyBrilliantParams& p) { return write(p.tiers); }};
}

template <class P>
Field<P> ratioRow(double P::*member) {
    return settings::number("ratio", member, {1, 3}, about("length / width"));
}

template <class P>
Field<P> cornerRow(double P::*member, std::string help) {
    return settings::number("corner", member, {1, 45}, about(std::move(help), "%"));
}

RoundBrilliantParams withValues(double table, double crown, double pavilion, double girdle, double star,
                                double lowerHalf, double culet) {
    RoundBrilliantParams p;
    p.tablePct = table, p.crownAngleDeg = crown, p.pavilionAngleDeg = pavilion, p.girdlePct = girdle;
    p.starPct = star, p.lowerHalfPct = lowerHalf, p.culetPct = culet;
    return p;
}

// Round outlines only choose the halves: the fancy shapes keep the faceters' halves, which stay in place when
// their planes are laid on a pointed outline (the trade's construction is defined on the circle).
CutShape roundShape(std::string name, std::string description, const RoundBrilliantParams& defaults) {
    std::vector<Field<RoundBrilliantParams>> rows = brilliantRows();
    rows.push_back(
        settings::choice("halves", &RoundBrilliantParams::halves, kHalvesLayoutNames,
                         about("trade: the trade's halves (DiamCalc, GIA reports); faceter: 3.75 deg "
                               "off the mains, another stone")));
    return tableShape(std::move(name), std::move(description), defaults, std::move(rows), makeRoundBrilliant);
}

CutShape fancyShape(std::string name, std::string description, FancyOutline outline, double ratio,
                    const RoundBrilliantParams& tiers, double corner = 0) {
    FancyBrilliantParams defaults;
    defaults.outline = outline, defaults.tiers = tiers, defaults.ratio = ratio;
    defaults.tiers.halves = HalvesLayout::Faceter;
    std::vector<Field<FancyBrilliantParams>> rows;
    for (auto& row : brilliantRows()) rows.push_back(ofTiers(std::move(row)));
    rows.push_back(ratioRow(&FancyBrilliantParams::ratio));
    if (corner > 0) {
        defaults.cornerPct = corner;
        rows.push_back(cornerRow(&FancyBrilliantParams::cornerPct, outline == FancyOutline::Cushion
                                                                       ? "corner radius, % of the width"
                                                                       : "corner cut, % of the width"));
    }
    return tableShape(std::move(name), std::move(description), defaults, std::move(rows), makeFancyBrilliant);
}

CutShape stepShape(std::string name, std::string description, const StepCutParams& defaults) {
    using P = StepCutParams;
    return tableShape(
        std::move(name), std::move(description), defaults,
        {
            ratioRow(&P::ratio),
            cornerRow(&P::cornerPct, "corner cut, % of the width"),
            settings::number("table", &P::tablePct, {20, 90}, about("table, % of the width", "%")),
            settings::number("crown", &P::crownAngleDeg, {10, 70},
                             about("crown angle of the step at the girdle", "deg")),
            settings::number("pavilion", &P::pavilionAngleDeg, {20, 80},
                             about("pavilion angle of the step at the girdle", "deg")),
            settings::number("girdle", &P::girdlePct, {0, 10}, about("girdle thickness", "%")),
            settings::number("crown_step", &P::crownStepDeg, {0, 20},
                             about("each crown step is this much flatter than the one outside it", "deg")),
            settings::number("pavilion_step", &P::pavilionStepDeg, {0, 20},
                             about("each pavilion step is this much flatter than the one outside it", "deg")),
            settings::count("crown_steps", &P::crownSteps, 1, 6, about("number of crown steps")),
            settings::count("pavilion_steps", &P::pavilionSteps, 1, 6, about("number of pavilion steps")),
        },
        makeStepCut);
}

CutShape singleShape() {
    using P = SingleCutParams;
    return tableShape(
        "single_cut", "single cut: table, 8 crown and 8 pavilion facets", P{},
        {
            settings::number("table", &P::tablePct, {20, 90}, about("table, corner to corner", "%")),
            settings::number("crown", &P::crownAngleDeg, {10, 60}, about("crown angle", "deg")),
            settings::number("pavilion", &P::pavilionAngleDeg, {20, 60}, about("pavilion angle", "deg")),
            settings::number("girdle", &P::girdlePct, {0.1, 10}, about("girdle thickness", "%")),
            settings::number("culet", &P::culetPct, {0, 30}, about("culet, flat to flat; 0 = pointed", "%")),
            settings::count("girdle_facets", &P::girdleFacets, 8, 400,
                            about("girdle sides, a multiple of 8")),
        },
        makeSingleCut);
}

CutShape roseShape() {
    using P = RoseCutParams;
    return tableShape(
        "rose_cut", "Dutch rose: a dome of 24 triangles on a flat base", P{},
        {
            settings::number("lower", &P::lowerAngleDeg, {10, 80},
                             about("slope of the 12 facets at the girdle", "deg")),
            settings::number("middle", &P::middleAngleDeg, {5, 75},
                             about("slope of the 6 middle facets", "deg")),
            settings::number("top", &P::topAngleDeg, {2, 70},
                             about("slope of the 6 facets meeting at the top", "deg")),
            settings::number("girdle", &P::girdlePct, {0.1, 10}, about("girdle thickness", "%")),
            settings::count("girdle_facets", &P::girdleFacets, 12, 396,
                            about("girdle sides, a multiple of 12")),
        },
        makeRoseCut);
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
        roundShape("round_brilliant_deep",
                   "round brilliant with a deep pavilion (P 43, above GIA's Excellent 40.6-41.8)", deep));
    shapes.push_back(roundShape(
        "round_brilliant_shallow",
        "round brilliant with a shallow pavilion (P 38.5, below GIA's Excellent 40.6-41.8)", shallow));
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
    shapes.push_back(singleShape());
    shapes.push_back(roseShape());
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
            std::vector<std::string> names;
            std::string list;
            for (const auto& p : shape.parameters) {
                names.push_back(p.name);
                list += (list.empty() ? "" : ", ") + p.name;
            }
            const std::optional<std::string> meant = closestName(name, names);
            throw Error(excerpt(name), excerpt(name) + ": " + shape.name + " has no parameter " +
                                           inQuotes(name) +
                                           (meant ? " (did you mean '" + *meant + "'?)" : "") +
                                           "; its parameters are: " + list);
        }
        const std::string unit = param->unit == "%" ? "%" : param->unit.empty() ? "" : " " + param->unit;
        if (!std::isfinite(value) || value < param->min || value > param->max)
            throw Error(name, name + " " + formatNumber(value) + ": must lie between " +
                                  formatNumber(param->min) + " and " + formatNumber(param->max) + unit);
        if (param->integer && value != std::floor(value))
            throw Error(name, name + " " + formatNumber(value) + ": must be a whole number");
        if (!param->choices.empty() && !(value >= 0 && value < double(param->choices.size())))
            throw Error(name, name + " " + formatNumber(value) + ": must be the index of one of " +
                                  choiceList(*param));
        out[name] = value;
    }
    return out;
}

PolygonMesh makeCut(const std::string& shape, const CutValues& values) {
    const CutShape& s = findCutShape(shape);
    return s.build(completeCutValues(s, values));
}

std::string cutFlag(const std::string& name) {
    std::string flag = "--" + name;
    std::replace(flag.begin(), flag.end(), '_', '-');
    return flag;
}

std::string cutCommandLine(const CutShape& shape, const CutValues& completeValues) {
    std::string out = shape.name;
    for (const auto& p : shape.parameters)
        out += " " + cutFlag(p.name) + " " + parameterText(p, completeValues.at(p.name));
    return out;
}

}  // namespace facetlight
