#include "sweep/sweep_axis.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cuts/facet_design.h"
#include "util/error.h"
#include "util/number_text.h"

namespace facetlight {
namespace {

std::vector<std::string> splitText(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, separator)) parts.push_back(part);
    if (!text.empty() && text.back() == separator) parts.push_back("");
    return parts;
}

double axisNumber(const std::string& axis, const std::string& token) {
    double v = 0;
    if (!parseNumber(token, v) || !std::isfinite(v))
        throw Error("sweep axis " + axis + ": '" + token + "' is not a number");
    return v;
}

}  // namespace

bool isTraceAxis(const std::string& name) {
    return std::find(kTraceAxes.begin(), kTraceAxes.end(), name) != kTraceAxes.end();
}

bool isChoiceAxis(const std::string& name) {
    return name == "material" || name == "light";
}

std::string SweepAxis::label(size_t i) const {
    return numeric() ? formatNumber(values[i]) : choices[i];
}

SweepAxis sweepRange(const std::string& name, double lo, double hi, double step) {
    const std::string range = formatNumber(lo) + ":" + formatNumber(hi) + ":" + formatNumber(step);
    if (!(step > 0))
        throw Error("sweep axis " + name + ": the step must be above 0, got " + formatNumber(step));
    if (hi < lo) throw Error("sweep axis " + name + ": the range " + range + " is inverted (HI below LO)");
    const double steps = std::floor((hi - lo) / step + 1e-9);
    if (steps + 1 > double(kMaxSweepPoints))
        throw Error("sweep axis " + name + ": " + range + " has more than " +
                    std::to_string(kMaxSweepPoints) + " values");
    // lo + i step, rounded to nine decimals so that 37.3 is the number a user typing 37.3 gets.
    SweepAxis axis{name, {}, {}};
    for (int i = 0; i <= int(steps); ++i) axis.values.push_back(std::round((lo + i * step) * 1e9) / 1e9);
    return axis;
}

SweepAxis parseSweepAxis(const std::string& text) {
    const size_t eq = text.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
        throw Error("sweep axis '" + text + "': write NAME=LO:HI:STEP or NAME=V1,V2,...");
    SweepAxis axis;
    axis.name = text.substr(0, eq);
    const std::string range = text.substr(eq + 1);
    if (isChoiceAxis(axis.name)) {
        for (const std::string& choice : splitText(range, ',')) {
            if (choice.empty()) throw Error("sweep axis " + axis.name + ": an empty name in '" + range + "'");
            axis.choices.push_back(choice);
        }
    } else if (range.find(':') != std::string::npos) {
        const std::vector<std::string> parts = splitText(range, ':');
        if (parts.size() != 3)
            throw Error("sweep axis " + axis.name + ": a range is LO:HI:STEP, got '" + range + "'");
        axis = sweepRange(axis.name, axisNumber(axis.name, parts[0]), axisNumber(axis.name, parts[1]),
                          axisNumber(axis.name, parts[2]));
    } else {
        for (const std::string& token : splitText(range, ','))
            axis.values.push_back(axisNumber(axis.name, token));
    }
    if (axis.size() > kMaxSweepPoints)
        throw Error("sweep axis " + axis.name + " has more than " + std::to_string(kMaxSweepPoints) +
                    " values");
    return axis;
}
}  // namespace facetlight
