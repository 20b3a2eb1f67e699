#pragma once
// A study's result files written into a folder, from the one table of them (core/study/result_files.h).
#include <filesystem>
#include <string>

#include "study/result_files.h"
#include "terminal_output.h"

namespace facetlight::cli {

// Writes the files the study made (stats.json last: its presence says the folder is complete) and returns
// their names, comma-separated.
inline std::string writeResultFiles(const std::filesystem::path& out, const StudyResult& result) {
    std::string names;
    for (const ResultFile& f : kResultFiles) {
        const std::string bytes = result.bytes(f);
        if (bytes.empty()) continue;
        writeFile(out / f.name, bytes);
        names += (names.empty() ? "" : ", ") + std::string(f.name);
    }
    return names;
}

}  // namespace facetlight::cli
