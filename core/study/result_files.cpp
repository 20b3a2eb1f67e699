#include "study/result_files.h"

namespace facetlight {

namespace {

bool isStats(const ResultFile& row) {
    return row.name == "stats.json";
}

// The row's index in kResultFiles: `row` is one of its elements.
size_t indexOf(const ResultFile& row) {
    return size_t(&row - kResultFiles.data());
}

}  // namespace

std::string StudyResult::bytes(const ResultFile& row) const {
    if (isStats(row)) return stats.is_null() ? std::string() : stats.dump(2) + "\n";
    return files_.at(indexOf(row));
}

void StudyResult::load(const ResultFile& row, std::string&& bytes) {
    if (isStats(row)) {
        stats = nlohmann::json::parse(bytes);
    } else {
        files_.at(indexOf(row)) = std::move(bytes);
    }
}

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
