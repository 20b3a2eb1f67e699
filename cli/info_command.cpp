// facetlight info: what a stone file holds, as a gem cutter reads it.
#include <cstdio>
#include <iostream>
#include <memory>

#include "commands.h"
#include "cuts/mesh_resolver.h"
#include "io/cutting_sheet.h"
#include "pictures/design_diagram.h"
#include "scene/scene.h"
#include "stone/stone_json.h"
#include "stone/stone_size.h"
#include "terminal_output.h"
#include "util/error.h"
#include "util/number_text.h"

namespace facetlight::cli {

namespace {

struct InfoOptions {
    std::string mesh;
    bool json = false;
    bool keepFrame = false;
    double sizeMm = SceneSettings{}.sizeMm;
    std::string material = SceneSettings{}.material;
    std::optional<double> density;
    std::string diagram;
    std::string rough;
};

nlohmann::json sizeJson(const StoneSize& s, double sizeMm, const MaterialChoice& material,
                        std::optional<double> density) {
    nlohmann::json j = {{"size_mm", sizeMm},     {"length_mm", s.lengthMm},
                        {"width_mm", s.widthMm}, {"depth_mm", s.depthMm},
                        {"volume_mm3", s.volumeMm3}, {"block_retention", s.blockRetention},
                        {"material", material.material.name()}};
    j["density_g_cm3"] = density ? nlohmann::json(*density) : nlohmann::json();
    j["carats"] = s.carats ? nlohmann::json(*s.carats) : nlohmann::json();
    return j;
}

void printText(const Stone& stone, const std::optional<CuttingSheet>& sheet, const StoneSize& size,
               double sizeMm, const MaterialChoice& material, std::optional<double> density,
               std::optional<double> roughShare) {
    std::printf("%s: %zu facets, %zu triangles, %s\n", stone.name.c_str(), stone.facets.size(),
                stone.triangles.size(), stone.convex ? "convex" : "not convex");
    if (!stone.frame.fileOrientation)
        std::printf("re-oriented: %s%s\n",
                    stone.frame.tableFacet.empty()
                        ? ""
                        : ("facet " + stone.frame.tableFacet + " turned " +
                           formatNumber("%.2f", stone.frame.turnedDeg) + " deg to face up as the table")
                              .c_str(),
                    stone.frame.longAxisTurned ? (stone.frame.tableFacet.empty() ? "long axis laid along x"
                                                                                 : "; long axis laid along x")
                                               : "");
    if (sheet) std::printf("\n%s", cuttingSheetText(*sheet).c_str());
    std::printf("\nat %.2f mm across: %.2f x %.2f x %.2f mm, volume %.1f mm^3", sizeMm, size.lengthMm,
                size.widthMm, size.depthMm, size.volumeMm3);
    if (size.carats)
        std::printf(", %.3f ct (%s, %.2f g/cm^3)", *size.carats, material.material.name().c_str(), *density);
    else
        std::printf(" (no weight: %s names no density; give --density)", material.material.name().c_str());
    std::printf("; keeps %.1f %% of its block", 100 * size.blockRetention);
    if (roughShare) std::printf(" and %.1f %% of the rough", 100 * *roughShare);
    std::printf("\n");
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
    CLI::App* cmd = app.add_subcommand(
        "info", "Describe a stone: its cutting sheet, size and weight, facets by region, proportions");
    cmd->add_option("--mesh", options->mesh, "OBJ, STL or GemCad .asc/.gem file, or a shipped shape name")
        ->required();
    cmd->add_flag("--json", options->json, "Print JSON instead of text");
    cmd->add_flag("--keep-frame", options->keepFrame,
                  "Keep a mesh's own orientation (GemCad designs always keep theirs)");
    cmd->add_option("--size-mm", options->sizeMm,
                    "The girdle diameter (the width of a fancy shape) the dimensions and weight are given at");
    cmd->add_option("--material", options->material,
                    "The material whose density gives the weight (auto: the design's own, else diamond)");
    cmd->add_option("--density", options->density, "Density in g/cm^3, for a material that names none");
    cmd->add_option("--rough", options->rough,
                    "A rough (OBJ, STL or design) in the same units and frame: report the share of it the stone keeps");
    cmd->add_option("--diagram", options->diagram,
                    "Also write the faceting diagram (crown, profile, pavilion, tiers) as a PNG to this file");
    cmd->callback([options] {
        StoneOptions stoneOptions;
        stoneOptions.keepFrame = options->keepFrame;
        const Stone stone = resolveStone(options->mesh, stoneOptions);
        SceneSettings scene;
        scene.material = options->material;
        const MaterialChoice material = chooseMaterial(scene, stone);
        if (options->density && !(*options->density > 0 && *options->density < 30))
            throw Error("--density must be a positive number of g/cm^3 below 30");
        const std::optional<double> density = options->density ? options->density : material.material.densityGcm3();
        const StoneSize size = stoneSize(stone, options->sizeMm, density);
        const std::optional<CuttingSheet> sheet = cuttingSheet(stone);
        if (!options->diagram.empty()) writeFile(options->diagram, encodePng(designDiagram(stone, sheet, size)));
        std::optional<double> roughShare;
        if (!options->rough.empty()) {
            StoneOptions asDrawn;
            asDrawn.keepFrame = true;
            const Stone drawn = options->keepFrame || stone.design ? stone : resolveStone(options->mesh, asDrawn);
            roughShare = roughRetention(drawn, resolveStone(options->rough, asDrawn));
        }
        if (options->json) {
            nlohmann::json j = stoneJson(stone);
            if (sheet) j["cutting_sheet"] = toJson(*sheet);
            j["size"] = sizeJson(size, options->sizeMm, material, density);
            if (roughShare) j["size"]["rough_retention"] = *roughShare;
            std::cout << j.dump(2) << "\n";
        } else {
            printText(stone, sheet, size, options->sizeMm, material, density, roughShare);
        }
    });
}

}  // namespace facetlight::cli
