#include "study/result_files.h"

namespace facetlight {

const std::array<ResultFile, 6> kResultFiles{{
    {"stats.csv", "text/csv", "stats.csv", "stats_csv", false,
     [](const StudyResult& r) { return r.statsCsv; },
     [](StudyResult& r, std::string&& b) { r.statsCsv = std::move(b); }},
    {"render.png", "image/png", "render.png", "render", true,
     [](const StudyResult& r) { return r.renderPng; },
     [](StudyResult& r, std::string&& b) { r.renderPng = std::move(b); }},
    {"heatmap.png", "image/png", "heatmap.png", "heatmap", true,
     [](const StudyResult& r) { return r.heatmapPng; },
     [](StudyResult& r, std::string&& b) { r.heatmapPng = std::move(b); }},
    {"heatmap.json", "application/json", "heatmap.json", "heatmap_layout", true,
     [](const StudyResult& r) { return r.heatmapLayout; },
     [](StudyResult& r, std::string&& b) { r.heatmapLayout = std::move(b); }},
    {"angular.png", "image/png", "angular.png", "angular", true,
     [](const StudyResult& r) { return r.angularPng; },
     [](StudyResult& r, std::string&& b) { r.angularPng = std::move(b); }},
    {"stats.json", "application/json", "stats", "stats", false,
     [](const StudyResult& r) { return r.stats.is_null() ? std::string() : r.stats.dump(2) + "\n"; },
     [](StudyResult& r, std::string&& b) { r.stats = nlohmann::json::parse(b); }},
}};

}  // namespace facetlight
