#pragma once
// The files a study leaves, described once: the CLI writes them into a folder, the launcher's child hands
// them back through one, the service stores them and serves them under /api/jobs/{id}/<route>.
#include <array>
#include <string>
#include <string_view>

#include "study/study.h"

namespace facetlight {

struct ResultFile {
    std::string_view name;                            // in a results folder, e.g. "stats.json"
    std::string_view mediaType;                       // what the service sends it as
    std::string_view route;                           // under the service's /api/jobs/{id}/
    std::string_view link;                            // its name among a finished job's links
    std::string_view needs;                           // linked only when the job's request has this
                                                      // dotted path as an object not switched off
                                                      // ("enabled": false) or a name ("render",
                                                      // "sweep.maximize", "fire_picture"); empty: every
                                                      // job but a sweep
    std::string (*bytes)(const StudyResult&);         // empty: the study made none
    void (*load)(StudyResult&, std::string&& bytes);  // the inverse
};

// In the order they are written: stats.json last, so that its presence says a folder is complete.
extern const std::array<ResultFile, 16> kResultFiles;

// Whether a finished job of this request has the file (`needs` above).
bool hasResultFile(const ResultFile& file, const nlohmann::json& request);

}  // namespace facetlight
