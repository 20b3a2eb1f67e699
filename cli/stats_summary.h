#pragma once
// What `trace` and `render` print for a person: the verdict first (when the viewer ran), then the figures of
// the trace, instead of the statistics' JSON (docs/stats-schema.md), which `--json` writes.
#include <cstdio>
#include <ostream>
#include <string>

#include <nlohmann/json.hpp>

namespace facetlight::cli {

// "41.23 +- 0.12 %" for a share and its standard error.
inline std::string shareText(double share, double stderr) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2f +- %.2f %%", 100 * share, 100 * stderr);
    return text;
}

inline void printStatsSummary(std::ostream& out, const nlohmann::json& stats) {
    const nlohmann::json& totals = stats.at("totals");
    if (const auto viewer = stats.find("viewer"); viewer != stats.end()) {
        const nlohmann::json& verdict = viewer->at("verdict");
        out << "Verdict: " << verdict.at("summary").get<std::string>() << "\n"
            << "  against " << viewer->at("reference").get<std::string>() << "\n";
        for (const nlohmann::json& sentence : verdict.at("figures"))
            out << "  " << sentence.get<std::string>() << "\n";
        out << "Faults:\n";
        for (const nlohmann::json& fault : viewer->at("faults")) {
            if (!fault.at("applies").get<bool>()) continue;
            out << (fault.at("present").get<bool>() ? "  FOUND " : "  none  ")
                << fault.at("text").get<std::string>() << "\n";
        }
    }
    out << "Trace: " << totals.at("photons").get<uint64_t>() << " photons, "
        << totals.at("hit").get<uint64_t>() << " met the stone, " << totals.at("entered").get<uint64_t>()
        << " entered\n";
    static const std::pair<const char*, const char*> kFigures[] = {
        {"crown_return", "crown return"},
        {"weighted_return", "cosine-weighted return"},
        {"cone_return_45", "return within 45 deg"},
        {"leakage", "leakage (pavilion, girdle)"},
    };
    for (const auto& [key, label] : kFigures) {
        char line[128];
        std::snprintf(
            line, sizeof line, "  %-28s %s\n", label,
            shareText(totals.at(key).get<double>(), totals.at(std::string(key) + "_stderr").get<double>())
                .c_str());
        out << line;
    }
    // A stone whose material absorbs (settings.absorption, docs/optics.md "Absorption"): how much of the
    // light it keeps, which the figures above have lost.
    const auto settings = stats.find("settings");
    if (settings != stats.end() && settings->contains("absorption") &&
        !settings->at("absorption").is_null()) {
        char line[128];
        std::snprintf(line, sizeof line, "  %-28s %s\n", "absorbed inside the stone",
                      shareText(totals.at("absorbed_share").get<double>(),
                                totals.at("absorbed_share_stderr").get<double>())
                          .c_str());
        out << line;
    }
}

}  // namespace facetlight::cli
