#include "sweep/sweep_request.h"

#include <algorithm>
#include <filesystem>

#include "optics/material.h"
#include "sweep/optimizer.h"
#include "sweep/sweep_figures.h"
#include "scene/scene.h"
#include "util/error.h"

namespace facetlight {
namespace {

using nlohmann::json;
using settings::FieldInfo;
using settings::FieldType;

std::string itemPath(const std::string& path, size_t i) {
    return path + "[" + std::to_string(i) + "]";
}

const std::vector<FieldInfo>& axisFields() {
    static const std::vector<FieldInfo> fields{
        settings::describe("name", FieldType::Text),     settings::describe("from", FieldType::Number),
        settings::describe("to", FieldType::Number),     settings::describe("step", FieldType::Number),
        settings::describe("values", FieldType::Object), settings::describe("choices", FieldType::Object)};
    return fields;
}

const json& requiredArray(const json& j, const std::string& path, size_t lo, size_t hi) {
    if (!j.is_array() || j.size() < lo || j.size() > hi)
        throw Error(
            path, path + " must be a list of " + std::to_string(lo) + " to " + std::to_string(hi) + " items");
    return j;
}

// {"name", "from", "to", "step"}, {"name", "values": [numbers]} or {"name", "choices": [names]}.
SweepAxis readAxis(const json& j, const std::string& path) {
    settings::checkObject(j, path, axisFields());
    if (!j.contains("name")) throw Error(path + ".name", path + ".name is required");
    const std::string name = settings::readText(j["name"], path + ".name");
    const bool range = j.contains("from") || j.contains("to") || j.contains("step");
    if (int(range) + int(j.contains("values")) + int(j.contains("choices")) != 1)
        throw Error(path, path + " takes either from, to and step, or values, or choices");
    SweepAxis axis{name, {}, {}};
    if (range) {
        double bound[3];
        const char* keys[3] = {"from", "to", "step"};
        for (int i = 0; i < 3; ++i) {
            const std::string at = path + "." + keys[i];
            if (!j.contains(keys[i])) throw Error(at, at + " is required with a range");
            bound[i] = settings::readNumber(j[keys[i]], at, {});
        }
        if (!(bound[2] > 0)) throw Error(path + ".step", path + ".step must be above 0");
        if (bound[1] < bound[0]) throw Error(path + ".to", path + ".to must not be below " + path + ".from");
        try {
            return sweepRange(name, bound[0], bound[1], bound[2]);
        } catch (const Error& e) {
            throw Error(path, e.what());
        }
    }
    const bool names = j.contains("choices");
    const std::string listPath = path + (names ? ".choices" : ".values");
    const json& list = requiredArray(j[names ? "choices" : "values"], listPath, 1, kMaxSweepPoints);
    for (size_t i = 0; i < list.size(); ++i) {
        if (names) {
            axis.choices.push_back(settings::readText(list[i], itemPath(listPath, i)));
        } else {
            axis.values.push_back(settings::readNumber(list[i], itemPath(listPath, i), {}));
        }
    }
    return axis;
}

json axisJson(const SweepAxis& a) {
    json j = {{"name", a.name}};
    if (a.numeric()) {
        j["values"] = a.values;
    } else {
        j["choices"] = a.choices;
    }
    return j;
}

settings::Field<SweepRequest> axesField() {
    return {settings::describe("axes", FieldType::Object, {"", "the varied quantities, one or two"}),
            [](SweepRequest& r, const json& j, const std::string& path) {
                r.axes.clear();
                for (size_t i = 0; i < requiredArray(j, path, 1, kMaxSweepAxes).size(); ++i)
                    r.axes.push_back(readAxis(j[i], itemPath(path, i)));
            },
            [](const SweepRequest& r) {
                json a = json::array();
                for (const SweepAxis& axis : r.axes) a.push_back(axisJson(axis));
                return a;
            }};
}

settings::Field<SweepRequest> setField() {
    return {
        settings::describe("set", FieldType::Object, {"", "parameters held at other than their defaults"}),
        [](SweepRequest& r, const json& j, const std::string& path) {
            if (!j.is_object()) throw Error(path, path + " must be an object of parameter values");
            r.set.clear();
            for (const auto& [name, value] : j.items())
                r.set[name] = settings::readNumber(value, settings::fieldPath(path, name), {});
        },
        [](const SweepRequest& r) { return json(r.set); }};
}

settings::Field<SweepRequest> figureField() {
    FieldInfo info = settings::describe("figure", FieldType::Choice, {"", "the figure drawn"});
    info.choices = sweepFigureNames();
    return {info,
            [](SweepRequest& r, const json& j, const std::string& path) {
                r.figures = {settings::readChoice(j, path, sweepFigureNames())};
            },
            [](const SweepRequest& r) { return json(r.figures.front()); }};
}

settings::Field<SweepRequest> maximizeField() {
    FieldInfo info =
        settings::describe("maximize", FieldType::Choice, {"", "the figure whose best design is searched"});
    info.choices = sweepFigureNames();
    return {info,
            [](SweepRequest& r, const json& j, const std::string& path) {
                r.maximize = j.is_null() ? std::string() : settings::readChoice(j, path, sweepFigureNames());
            },
            [](const SweepRequest& r) { return r.maximize.empty() ? json(nullptr) : json(r.maximize); }};
}

settings::Field<SweepRequest> constraintsField() {
    return {settings::describe("constraints", FieldType::Object, {"", "NAME<=VALUE or NAME>=VALUE"}),
            [](SweepRequest& r, const json& j, const std::string& path) {
                r.constraints.clear();
                for (size_t i = 0; i < requiredArray(j, path, 0, 16).size(); ++i) {
                    const std::string at = itemPath(path, i);
                    const std::string text = settings::readText(j[i], at);
                    try {
                        parseSweepConstraint(text);
                    } catch (const Error& e) {
                        throw Error(at, e.what());
                    }
                    r.constraints.push_back(text);
                }
            },
            [](const SweepRequest& r) { return json(r.constraints); }};
}

}  // namespace

const settings::Schema<SweepRequest>& sweepRequestSchema() {
    static const settings::Schema<SweepRequest> schema(
        {axesField(), setField(), figureField(), maximizeField(), constraintsField(),
         settings::count("refine_rounds", &SweepRequest::refineRounds, 0, 6,
                         {"--refine-rounds", "with maximize: finer grids after the sweep"})},
        [](const SweepRequest& r, const std::string& path) {
            if (r.axes.empty()) {
                const std::string at = settings::fieldPath(path, "axes");
                throw Error(at, at + " is required: one or two varied quantities");
            }
            if (r.maximize.empty() && !r.constraints.empty()) {
                const std::string at = settings::fieldPath(path, "constraints");
                throw Error(at, at + " applies to a search: set maximize too");
            }
        });
    return schema;
}

namespace {

// Whether a point with these settings absorbs: a job's spectrum, else its named material's (an `n`, "auto"
// and a design file's index name no coloured material).
bool absorbs(const TraceSettings& t) {
    if (t.absorption) return t.absorption->absorbs();
    const std::optional<MaterialChoice> named = namedMaterial(t);
    return named && named->material.absorption() && named->material.absorption()->absorbs();
}

// With the colour view: it sees the stone face-up under a dome of its own, so the light's axes change none of
// its figures; and its figures measure absorption, so some point must absorb.
void checkColourPlan(const SweepPlan& plan) {
    if (!plan.colour) return;
    for (size_t i = 0; i < plan.axes.size(); ++i) {
        const std::string& name = plan.axes[i].name;
        if (name == "tilt" || name == "head_shadow" || name == "light") {
            const std::string at = itemPath("sweep.axes", i);
            throw Error(at, at + ": the colour view sees the stone face-up under a dome of its own, so " +
                                name + " changes none of the colour figures; sweep " + name + " without it");
        }
    }
    const std::vector<SweepPoint> points = sweepPoints(plan);
    if (std::none_of(points.begin(), points.end(), [](const SweepPoint& p) { return absorbs(p.trace); })) {
        const TraceSettings& t = plan.trace;
        // The job's own spectrum replaces every point's material's, so it is the one at fault.
        if (t.absorption)
            throw Error(
                "absorption",
                "the colour figures measure absorption, and no point of the sweep absorbs (the job's "
                "absorption is 0 at every wavelength, in place of the material's): give it coefficients "
                "or concentrations above 0, or leave it out for a coloured material's own");
        const std::string name = chosenMaterialName(t);
        const std::string what = t.constantIndex  ? name
                                 : name == "auto" ? "the material auto, diamond or a design's own index,"
                                                  : "the material " + name;
        throw Error(
            "material",
            "the colour figures measure absorption, and no point of the sweep absorbs (" + what +
                " is clear): choose a coloured material (blue_sapphire, emerald, ...: docs/optics.md, "
                "\"Coloured materials\") or give an absorption spectrum");
    }
}

// An optic axis along the table's normal (tilt 0 or 180 deg) has no azimuth: turning it changes no figure, so
// an azimuth axis needs the axis tilted, or a tilt axis beside it. A biaxial stone's Z turned over (tilt 180)
// is the exception: its X lies at 180 + 2 azimuth - rotation deg there (OpticAxisSettings::principalAxes),
// so the azimuth turns it.
void checkAzimuthPlan(const SweepPlan& plan) {
    const auto named = [&](const char* name) {
        return std::find_if(plan.axes.begin(), plan.axes.end(),
                            [&](const SweepAxis& a) { return a.name == name; });
    };
    const auto azimuth = named("optic_axis_azimuth");
    const double tilt = plan.trace.opticAxis.tiltDeg;
    const bool turnsX = tilt == 180 && chosenOptic(plan.trace) == Optic::Biaxial;
    if (azimuth == plan.axes.end() || named("optic_axis_tilt") != plan.axes.end() ||
        (tilt != 0 && tilt != 180) || turnsX)
        return;
    const std::string at = itemPath("sweep.axes", size_t(azimuth - plan.axes.begin()));
    throw Error(at, at + ": the optic axis lies along the table's normal (optic_axis tilt " +
                        std::string(tilt == 0 ? "0" : "180") +
                        " deg), where its azimuth changes nothing; tilt it (optic_axis.tilt_deg, "
                        "--optic-axis-tilt) or sweep optic_axis_tilt too");
}

// Checks `plan` (its shape already found) against the request, naming the field at fault.
SweepPlan checkedPlan(SweepPlan plan, const SweepRequest& request, const TraceSettings& trace) {
    try {
        completeCutValues(plan.cutShape(), request.set);
    } catch (const Error& e) {
        throw e.within("sweep.set");
    }
    for (size_t i = 0; i < request.axes.size(); ++i) {
        SweepPlan one = plan;
        one.axes = {request.axes[i]};
        try {
            one.validate();
        } catch (const Error& e) {
            throw Error(itemPath("sweep.axes", i), e.what());
        }
        if (!request.maximize.empty() && !request.axes[i].numeric())
            throw Error("sweep.maximize",
                        "the best design is searched over numbers; " + request.axes[i].name + " takes names");
    }
    try {
        plan.validate();
    } catch (const Error& e) {
        throw Error("sweep.axes", e.what());
    }
    checkAzimuthPlan(plan);
    checkColourPlan(plan);
    checkSweepFigures(request, trace, plan.colour.has_value());
    return plan;
}

}  // namespace

SweepPlan planSweep(const std::string& shape, const SweepRequest& request, const TraceSettings& trace,
                    const std::optional<ColourSettings>& colour) {
    try {
        findCutShape(shape);
    } catch (const Error& e) {
        throw Error("mesh", e.what());
    }
    return checkedPlan({shape, nullptr, request.set, request.axes, trace, colour}, request, trace);
}

bool isLibraryShape(const std::string& name) {
    return std::any_of(cutShapes().begin(), cutShapes().end(), [&](const CutShape& s) { return s.name == name; });
}

SweepPlan planSweepOf(const std::string& shapeOrPath, const SweepRequest& request, const TraceSettings& trace,
                      const std::optional<ColourSettings>& colour) {
    if (isLibraryShape(shapeOrPath) || !std::filesystem::exists(shapeOrPath))
        return planSweep(shapeOrPath, request, trace, colour);
    std::shared_ptr<const FileShape> file;
    try {
        file = fileShape(shapeOrPath);
    } catch (const Error& e) {
        throw Error("mesh", e.what());
    }
    return planSweep(std::move(file), request, trace, colour);
}

SweepPlan planSweep(std::shared_ptr<const FileShape> file, const SweepRequest& request,
                    const TraceSettings& trace, const std::optional<ColourSettings>& colour) {
    const std::string name = file->shape.name;
    return checkedPlan({name, std::move(file), request.set, request.axes, trace, colour}, request, trace);
}

void checkSweepFigures(const SweepRequest& request, const TraceSettings& trace, bool colour,
                       const SweepFigureFields& fields) {
    const auto check = [&](const std::string& name, const std::string& field) {
        try {
            checkSweepFigure(name, trace, colour);
        } catch (const Error& e) {
            throw Error(field, field + ": " + e.what());
        }
    };
    for (const std::string& f : request.figures) check(f, fields.figure);
    if (!request.maximize.empty()) check(request.maximize, fields.maximize);
    for (size_t i = 0; i < request.constraints.size(); ++i) {
        const std::string quantity = parseSweepConstraint(request.constraints[i]).quantity;
        if (!quantity.ends_with("_pct"))
            check(quantity, fields.indexed ? itemPath(fields.constraints, i) : fields.constraints);
    }
}

}  // namespace facetlight
