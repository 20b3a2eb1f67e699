#pragma once
// The verdict on a stone (docs/physics.md, "Verdict"): each viewer figure against the GIA reference cut seen
// the same way, in words and numbers; the faults a gemologist names, recognised from the face-up measures;
// and one light-performance score with fixed, documented weights that never replaces the figures.
#include <array>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "viewer/viewer_figures.h"

namespace facetlight {

// A fault and the face-up measure that shows it: present when the measure exceeds the threshold (the
// thresholds and the stones they were set on: docs/physics.md, "Verdict").
struct FaultRule {
    std::string_view key, name, meaning;
    ViewerFigure (ViewerFigures::*measure)() const;
    double threshold;
    bool elongatedOnly;  // only for stones at least kElongated times as long as wide
};
inline constexpr double kElongated = 1.2;
inline constexpr std::array<FaultRule, 5> kFaultRules{{
    {"fish_eye", "fish-eye", "the girdle's reflection seen in the table", &ViewerFigures::girdleInTable, 0.05,
     false},
    {"nail_head", "nail-head", "the table's centre dark with the viewer's head",
     &ViewerFigures::headInTableCentre, 0.75, false},
    {"windowing", "windowing", "the background seen through the table", &ViewerFigures::seeThroughTable, 0.25,
     false},
    {"extinction", "extinction", "face-up area dark however the stone is rocked", &ViewerFigures::extinction,
     0.08, false},
    {"bow_tie", "bow-tie", "a dark band across the middle of an elongated stone", &ViewerFigures::darkMiddle,
     0.25, true},
}};

// The light-performance score: 100 times the weighted mean of brightness, fire, scintillation and contrast,
// each as a ratio to the reference's; contrast counts by its balance, min(ratio, 1 / ratio), since a viewer
// wants the reference's pattern of light and dark, not more and not less (docs/physics.md, "Verdict").
struct ScoreWeight {
    std::string_view figure;
    double weight;
    bool balanced;
};
inline constexpr std::array<ScoreWeight, 4> kScoreWeights{{{"brightness", 0.4, false},
                                                           {"fire", 0.2, false},
                                                           {"scintillation", 0.2, false},
                                                           {"contrast", 0.2, true}}};

struct FigureComparison {
    const ViewerFigureInfo* info = nullptr;
    ViewerFigure stone, reference;
    ViewerFigure difference;  // stone / reference - 1, in percent
    std::string text;         // "brightness 3.1 % +- 0.2 below the GIA reference"
};

struct FaultFinding {
    const FaultRule* rule = nullptr;
    ViewerFigure measure;
    bool applies = true;  // false for an elongated-only fault on a stone that is not elongated
    bool present = false;
    std::string text;
};

struct Verdict {
    std::string reference;  // what the figures are compared with
    std::vector<FigureComparison> figures;
    std::vector<FaultFinding> faults;
    ViewerFigure score;
    std::string summary;  // one line: the score, the largest differences, the faults
};

// The GIA reference round brilliant (the cut library's round_brilliant at its defaults) in the job's
// material, seen with the job's viewer settings. Each distinct set of settings is traced once per process.
const ViewerFigures& referenceFigures(const TraceSettings& trace, RunControl* control = nullptr);
extern const char* const kReferenceName;

Verdict judge(const Stone& stone, const ViewerFigures& figures, const ViewerFigures& reference);

// The `viewer` member of stats.json: {"settings", "figures": {key: {"value", "stderr", "set_up",
// "reference", "difference_pct", "difference_pct_stderr"}}, "measures", "faults", "score", "verdict",
// "reference"} (docs/stats-schema.md).
nlohmann::json toJson(const ViewerFigures& figures, const Verdict& verdict, const ViewerSettings& settings);

// The whole viewer report of a stone: its figures, the reference's, the verdict. Null when the settings turn
// the viewer off; throws Canceled when control is cancelled while it runs.
nlohmann::json viewerReport(const Stone& stone, const TraceSettings& trace, RunControl* control = nullptr);

}  // namespace facetlight
