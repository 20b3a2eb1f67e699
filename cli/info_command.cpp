// facetlight info: what a stone file holds, as a gem cutter reads it.
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "cuts/mesh_resolver.h"
#include "stone/stone_json.h"
#include "terminal_output.h"

namespace facetlight::cli {

namespace {

struct InfoOptions {
    std::string mesh;
    bool json = false;
};

void printText(const Stone& stone) {
    std::printf("%s: %zu facets, %zu triangles, %s\n", stone.name.c_str(), stone.facets.size(),
                stone.triangles.size(), stone.convex ? "convex" : "not convex");
    const Proportions& p = stone.proportions;
    std::printf("\nproportions (length %.4g x width %.4g)\n", p.length, p.width);
    printProportions(p);
    for (int r = 0; r < kRegionCount; ++r) {
        const Region region = Region(r);
        std::printf("\n%s: %d facets\n", std::string(regionName(region)).c_str(), stone.facetCount(region));
        for (const auto& f : stone.facets)
            if (f.region == region)
                std::printf("  %4u  %-20s area %9.5f  normal (%+.4f, %+.4f, %+.4f)\n", f.id, f.name.c_str(),
                            f.area, f.normal.x, f.normal.y, f.normal.z);
    }
    for (const auto& w : stone.warnings) std::printf("\nwarning: %s\n", w.c_str());
}

}  // namespace

void addInfoCommand(CLI::App& app) {
    auto options = std::make_shared<InfoOptions>();
    CLI::App* cmd = app.add_subcommand("info", "Describe a stone: facets by region, proportions, convexity");
    cmd->add_option("--mesh", options->mesh, "OBJ, STL or GemCad .asc file, or a shipped shape name")
        ->required();
    cmd->add_flag("--json", options->json, "Print JSON instead of text");
    cmd->callback([options] {
        const Stone stone = resolveStone(options->mesh);
        if (options->json)
            std::cout << stoneJson(stone).dump(2) << "\n";
        else
            printText(stone);
    });
}

}  // namespace facetlight::cli
