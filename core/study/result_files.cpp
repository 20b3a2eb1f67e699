#include "study/result_files.h"

namespace facetlight {

const std::array<ResultFile, 16> kResultFiles{{
    {"best.obj", "text/plain", "best.obj", "best_obj", "sweep.maximize",
     [](const StudyResult& r) { return r.bestObj; },
     [](StudyResult& r, std::string&& b) { r.bestObj = std::move(b); }},
    {"best.json", "application/json", "best.json", "best", "sweep.maximize",
     [](const StudyResult& r) { return r.bestJson; },
     [](StudyResult& r, std::string&& b) { r.bestJson = std::move(b); }},
    {"sweep.csv", "text/csv", "sweep.csv", "sweep_csv", "sweep",
     [](const StudyResult& r) { return r.sweepCsv; },
     [](StudyResult& r, std::string&& b) { r.sweepCsv = std::move(b); }},
    {"sweep.png", "image/png", "sweep.png", "sweep_picture", "sweep",
     [](const StudyResult& r) { return r.sweepPng; },
     [](StudyResult& r, std::string&& b) { r.sweepPng = std::move(b); }},
    // Last of a sweep's: its presence says the folder is complete.
    {"sweep.json", "application/json", "sweep.json", "sweep", "sweep",
     [](const StudyResult& r) { return r.sweepJson; },
     [](StudyResult& r, std::string&& b) { r.sweepJson = std::move(b); }},
    {"stats.csv", "text/csv", "stats.csv", "stats_csv", "", [](const StudyResult& r) { return r.statsCsv; },
     [](StudyResult& r, std::string&& b) { r.statsCsv = std::move(b); }},
    {"render.png", "image/png", "render.png", "render", "render",
     [](const StudyResult& r) { return r.renderPng; },
     [](StudyResult& r, std::string&& b) { r.renderPng = std::move(b); }},
    {"fire.png", "image/png", "fire.png", "fire_picture", "fire_picture",
     [](const StudyResult& r) { return r.firePng; },
     [](StudyResult& r, std::string&& b) { r.firePng = std::move(b); }},
    {"heatmap.png", "image/png", "heatmap.png", "heatmap", "render",
     [](const StudyResult& r) { return r.heatmapPng; },
     [](StudyResult& r, std::string&& b) { r.heatmapPng = std::move(b); }},
    {"heatmap.json", "application/json", "heatmap.json", "heatmap_layout", "render",
     [](const StudyResult& r) { return r.heatmapLayout; },
     [](StudyResult& r, std::string&& b) { r.heatmapLayout = std::move(b); }},
    {"heatmap_fire.png", "image/png", "heatmap_fire.png", "heatmap_fire", "fire",
     [](const StudyResult& r) { return r.fireHeatmapPng; },
     [](StudyResult& r, std::string&& b) { r.fireHeatmapPng = std::move(b); }},
    {"angular.png", "image/png", "angular.png", "angular", "render",
     [](const StudyResult& r) { return r.angularPng; },
     [](StudyResult& r, std::string&& b) { r.angularPng = std::move(b); }},
    {"aset.png", "image/png", "aset.png", "aset", "aset", [](const StudyResult& r) { return r.asetPng; },
     [](StudyResult& r, std::string&& b) { r.asetPng = std::move(b); }},
    {"tilt.webp", "image/webp", "tilt.webp", "tilt_animation", "tilt_series",
     [](const StudyResult& r) { return r.tiltWebp; },
     [](StudyResult& r, std::string&& b) { r.tiltWebp = std::move(b); }},
    {"tilt.png", "image/png", "tilt.png", "tilt_chart", "tilt_series",
     [](const StudyResult& r) { return r.tiltChartPng; },
     [](StudyResult& r, std::string&& b) { r.tiltChartPng = std::move(b); }},
    {"stats.json", "application/json", "stats", "stats", "",
     [](const StudyResult& r) { return r.stats.is_null() ? std::string() : r.stats.dump(2) + "\n"; },
     [](StudyResult& r, std::string&& b) { r.stats = nlohmann::json::parse(b); }},
}};

bool hasResultFile(const ResultFile& file, const nlohmann::json& request) {
    if (file.needs.empty()) return !(request.contains("sweep") && request["sweep"].is_object());
    const nlohmann::json* at = &request;
    std::string_view path = file.needs;
    while (!path.empty()) {
        const size_t dot = path.find('.');
        const std::string key(path.substr(0, dot));
        if (!at->is_object() || !at->contains(key)) return false;
        at = &(*at)[key];
        path = dot == std::string_view::npos ? std::string_view() : path.substr(dot + 1);
    }
    // "fire": {"enabled": false} asks for no fire heat-map.
    return (at->is_object() && at->value("enabled", true)) || at->is_string();
}

}  // namespace facetlight
