#include "job_budget.h"

#include <cmath>

#include "study/cost_calibration.h"
#include "util/error.h"
#include "util/number_text.h"

namespace facetlight::server {

std::string formatSeconds(double seconds) {
    return formatNumber(seconds < 10 ? "%.1f" : "%.0f", seconds);
}

JobCost JobBudget::estimate(const StudySettings& settings, int threads) const {
    return estimateJobCost(settings, rates_, threads);
}

std::string JobBudget::refusal(const JobCost& cost, int threads) const {
    if (maxSeconds_ <= 0 || cost.seconds <= maxSeconds_) return {};
    const CostPart& part = cost.largest();
    return part.name + ": about " + formatSeconds(part.seconds) + " s of the " + formatSeconds(maxSeconds_) +
           " s a job may take on this server (" + part.size + "); the whole job about " +
           formatSeconds(cost.seconds) + " s with " + std::to_string(threads) +
           (threads == 1 ? " thread" : " threads") + (part.field.empty() ? "" : ": lower " + part.field);
}

void JobBudget::check(const StudySettings& settings, int threads) const {
    if (maxSeconds_ <= 0) return;
    const JobCost cost = estimate(settings, threads);
    if (const std::string why = refusal(cost, threads); !why.empty()) throw Error(cost.largest().field, why);
}

std::string JobBudget::overrun(double ranSeconds) const {
    return "stopped: ran " + formatSeconds(ranSeconds) + " s, over its budget of " +
           formatSeconds(runSeconds()) + " s (twice the " + formatSeconds(maxSeconds_) +
           " s a job may take on this server)";
}

const CostRates& machineCostRates() {
    static const CostRates rates = calibrateCostRates();
    return rates;
}

}  // namespace facetlight::server
