// facetlight cut: build a design of the cut library from trade proportions and write it as OBJ.
#include <cstdio>
#include <iostream>
#include <map>
#include <memory>
#include <set>

#include "commands.h"
#include "cuts/cut_library.h"
#include "io/obj_writer.h"
#include "stone/stone.h"
#include "terminal_output.h"
#include "util/error.h"

namespace facetlight::cli {

namespace {

struct CutOptions {
    std::string shape;
    std::string out;
    bool list = false;
    CutValues values;
};

void printList() {
    for (const auto& shape : cutShapes()) {
        std::printf("%s: %s\n", shape.name.c_str(), shape.description.c_str());
        for (const auto& p : shape.parameters) {
            std::string range = "[" + parameterText(p, p.min) + ", " + parameterText(p, p.max) + "]";
            if (!p.choices.empty()) {
                range.clear();
                for (const auto& c : p.choices) range += (range.empty() ? "" : "|") + c;
            }
            std::printf("  %-17s %8s  %s %-4s %s\n", cutFlag(p.name).c_str(),
                        parameterText(p, p.defaultValue).c_str(), range.c_str(), p.unit.c_str(),
                        p.help.c_str());
        }
    }
}

void printSummary(const Stone& stone, const std::string& path) {
    std::printf("wrote %s: %zu facets (table %d, crown %d, girdle %d, pavilion %d)\n", path.c_str(),
                stone.facets.size(), stone.facetCount(Region::Table), stone.facetCount(Region::Crown),
                stone.facetCount(Region::Girdle), stone.facetCount(Region::Pavilion));
    printProportions(stone.proportions);
}

}  // namespace

void addCutCommand(CLI::App& app) {
    auto options = std::make_shared<CutOptions>();
    CLI::App* cmd =
        app.add_subcommand("cut", "Build a shape of the cut library from its proportions, as OBJ");
    cmd->add_option("shape", options->shape, "Shape name (see --list)");
    cmd->add_option("--out", options->out, "OBJ file to write");
    cmd->add_flag("--list", options->list,
                  "List the shapes with their parameters, defaults and valid ranges");
    std::set<std::string> seen;
    for (const auto& shape : cutShapes())
        for (const auto& p : shape.parameters) {
            if (!seen.insert(p.name).second) continue;
            const std::string name = p.name;
            if (!p.choices.empty()) {
                cmd->add_option_function<std::string>(
                       cutFlag(name),
                       [options, param = p](const std::string& v) {
                           options->values[param.name] = choiceIndex(param, v);
                       },
                       p.help)
                    ->type_name("NAME");
                continue;
            }
            cmd->add_option_function<double>(
                   cutFlag(name), [options, name](const double& v) { options->values[name] = v; }, p.help)
                ->type_name(p.unit.empty() ? "NUMBER" : p.unit);
        }
    cmd->callback([options] {
        if (options->list) return printList();
        if (options->shape.empty()) throw Error("cut: name a shape (facetlight cut --list shows them)");
        if (options->out.empty()) throw Error("cut: say where to write the OBJ with --out FILE.obj");
        const CutShape& shape = findCutShape(options->shape);
        CutValues given;
        for (const auto& [name, value] : options->values) given[name] = value;
        const CutValues values = completeCutValues(shape, given);
        const PolygonMesh mesh = shape.build(values);
        const Stone stone = Stone::build(mesh, shape.name);
        writeTextFile(options->out, objText(mesh, "facetlight cut " + cutCommandLine(shape, values)));
        printSummary(stone, options->out);
    });
}

}  // namespace facetlight::cli
