#pragma once
// The shipped designs by their snake_case names (the same in the CLI, the API and meshes/): each shape's
// parameters with defaults and valid ranges, and makeCut() to build one.
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "geometry/polygon_mesh.h"

namespace facetlight {

struct CutParameter {
    std::string name;  // snake_case key; the command-line flag is --name with '-' for '_'
    std::string unit;  // "%", "deg", "" (a ratio or a count)
    std::string help;
    double defaultValue = 0, min = 0, max = 0;
    bool integer = false;
    std::vector<std::string> choices = {};  // a named choice: the value is the chosen name's index
};

using CutValues = std::map<std::string, double>;

struct CutShape {
    std::string name;
    std::string description;
    std::vector<CutParameter> parameters;
    std::function<PolygonMesh(const CutValues&)> build;  // takes every parameter, already checked
};

const std::vector<CutShape>& cutShapes();
// Throws Error listing the known shapes when there is no such shape.
const CutShape& findCutShape(const std::string& name);
std::string knownShapeNames();  // comma-separated

// The shape's defaults with `values` overriding some of them. Throws Error for an unknown shape or parameter,
// a value outside its range or a fraction given for a count, and for proportions that cannot make the stone.
CutValues completeCutValues(const CutShape& shape, const CutValues& values);
PolygonMesh makeCut(const std::string& shape, const CutValues& values = {});

// The index of a choice parameter's value `name`. Throws Error listing the choices.
double choiceIndex(const CutParameter& param, const std::string& name);
// A parameter's value as the command line writes it: a choice's name, else the number.
std::string parameterText(const CutParameter& param, double value);

// "--lower-half" for lower_half: a parameter's command-line flag.
std::string cutFlag(const std::string& name);

// "round_brilliant --table 57 --crown 34 ...": the command-line arguments that build this design.
std::string cutCommandLine(const CutShape& shape, const CutValues& completeValues);

}  // namespace facetlight
