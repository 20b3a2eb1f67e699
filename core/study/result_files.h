#pragma once
// The files a study leaves, described once: the CLI writes them into a folder, the launcher's child hands
// them back through one, the service stores them and serves them under /api/jobs/{id}/<route>. A study's
// result holds each one's bytes by its row.
#include <array>
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace facetlight {

struct ResultFile {
    std::string_view name;       // in a results folder, e.g. "stats.json"
    std::string_view mediaType;  // what the service sends it as
    std::string_view route;      // under the service's /api/jobs/{id}/
    std::string_view link;       // its name among a finished job's links
    std::string_view needs;      // linked only when the job's request has this dotted path as an object not
                                 // switched off ("enabled": false) or a name ("render", "sweep.maximize",
                                 // "fire_picture"); empty: every job but a sweep
};

// In the order they are written: stats.json last, so that its presence says a folder is complete.
inline constexpr std::array<ResultFile, 23> kResultFiles{{
    {"best.obj", "text/plain", "best.obj", "best_obj", "sweep.maximize"},
    // The best design as GemCad .asc (docs/gemcad.md): a design's tiers as tweaked, a mesh's facet planes.
    {"best.asc", "text/plain", "best.asc", "best_asc", "sweep.maximize"},
    {"best.json", "application/json", "best.json", "best", "sweep.maximize"},
    {"sweep.csv", "text/csv", "sweep.csv", "sweep_csv", "sweep"},
    {"sweep.png", "image/png", "sweep.png", "sweep_picture", "sweep"},
    // Last of a sweep's: its presence says the folder is complete.
    {"sweep.json", "application/json", "sweep.json", "sweep", "sweep"},
    {"stats.csv", "text/csv", "stats.csv", "stats_csv", ""},
    {"render.png", "image/png", "render.png", "render", "render"},
    {"fire.png", "image/png", "fire.png", "fire_picture", "fire_picture"},
    // The heat-map and its facets in pixels (docs/stats-schema.md) come with every study, rendered or not
    // (heatmap_fire.png's facets lie where heatmap.png's do).
    {"heatmap.png", "image/png", "heatmap.png", "heatmap", ""},
    {"heatmap.json", "application/json", "heatmap.json", "heatmap_layout", ""},
    // The stone as traced, facet by facet in mm, for the page's 3-D view (docs/stats-schema.md).
    {"stone.json", "application/json", "stone.json", "stone", ""},
    {"heatmap_fire.png", "image/png", "heatmap_fire.png", "heatmap_fire", "fire"},
    {"angular.png", "image/png", "angular.png", "angular", "render"},
    {"aset.png", "image/png", "aset.png", "aset", "aset"},
    {"tilt.webp", "image/webp", "tilt.webp", "tilt_animation", "tilt_series"},
    {"tilt.png", "image/png", "tilt.png", "tilt_chart", "tilt_series"},
    // The stone turned between crossed polarisers (docs/optics.md, "The polariscope").
    {"polariscope.png", "image/png", "polariscope.png", "polariscope_chart", "polariscope"},
    {"polariscope.webp", "image/webp", "polariscope.webp", "polariscope_animation", "polariscope"},
    // The stone face-up with its pavilion's edges doubled (docs/optics.md, "The doubling").
    {"doubling.png", "image/png", "doubling.png", "doubling", "doubling"},
    // The stone face-up in true colour (docs/optics.md, "The colour a viewer sees").
    {"colour.png", "image/png", "colour.png", "colour", "colour"},
    // The faceting diagram: crown, profile and pavilion with the cutting sheet's tiers (docs/gemcad.md).
    {"diagram.png", "image/png", "diagram.png", "diagram", ""},
    {"stats.json", "application/json", "stats", "stats", ""},
}};

// Whether a finished job of this request has the file (`needs` above).
bool hasResultFile(const ResultFile& file, const nlohmann::json& request);

// A file of kResultFiles by its name, looked up when compiled: a name the table lacks does not compile.
class ResultFileName {
  public:
    consteval ResultFileName(const char* name) : index_(find(name)) {}
    size_t index() const { return index_; }

  private:
    static consteval size_t find(std::string_view name) {
        for (size_t i = 0; i < kResultFiles.size(); ++i)
            if (kResultFiles[i].name == name) return i;
        throw "not a file of kResultFiles";
    }
    size_t index_;
};

// What a study leaves: its statistics document, and the bytes of every other file of kResultFiles (empty:
// the study made none; the render's pictures come only with a render, a sweep's files only from a sweep).
class StudyResult {
  public:
    nlohmann::json stats;  // the statistics document (docs/stats-schema.md), written as stats.json

    // result.file("render.png") = encodePng(...). stats.json is `stats`, not a file here.
    std::string& file(ResultFileName name) { return files_[name.index()]; }
    const std::string& file(ResultFileName name) const { return files_[name.index()]; }
    // A row of kResultFiles as written into a folder; empty: the study made none.
    std::string bytes(const ResultFile& row) const;
    // The inverse, for a file read back from a folder.
    void load(const ResultFile& row, std::string&& bytes);

  private:
    std::array<std::string, kResultFiles.size()> files_;  // by row of kResultFiles; stats.json's unused
};

}  // namespace facetlight
