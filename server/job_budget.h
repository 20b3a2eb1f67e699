#pragma once
// How long a job may take (--max-job-seconds; docs/reliability.md, "How long a job may take"): a job whose
// estimate (study/job_cost.h, from this machine's rates) passes the limit is refused before anything is
// stored, and a running job that outlives twice the limit is stopped. The estimate is core's; the limit, the
// refusal and the stop are the service's.
#include <string>

#include "study/job_cost.h"

namespace facetlight::server {

class JobBudget {
  public:
    // `maxSeconds` 0: no limit, nothing refused or stopped.
    JobBudget(double maxSeconds, const CostRates& rates) : maxSeconds_(maxSeconds), rates_(rates) {}

    double maxSeconds() const { return maxSeconds_; }
    // The job's cost with `threads` workers, from this machine's rates.
    JobCost estimate(const StudySettings& settings, int threads) const;
    // Why a job of this cost with `threads` workers is refused, or empty when it is within the limit:
    // "render: about 5400 s of the 600 s a job may take on this server (2048x2048 pixels x 256 samples x
    // depth 64); the whole job about 5600 s with 2 threads: lower render.samples".
    std::string refusal(const JobCost& cost, int threads) const;
    // Throws Error with the refusal, naming the largest part's field, when the job's cost passes the limit.
    void check(const StudySettings& settings, int threads) const;
    // How long a job may run before it is stopped: twice the limit, a margin as long as the limit for an
    // estimate that fell short (0: no limit).
    double runSeconds() const { return 2 * maxSeconds_; }
    // Why a job was stopped: "stopped: ran 1201 s, over its budget of 1200 s (twice the 600 s a job may take
    // on this server)".
    std::string overrun(double ranSeconds) const;

  private:
    double maxSeconds_;
    CostRates rates_;
};

// This machine's rates, measured once per process on first use (the server's start): calibrateCostRates().
const CostRates& machineCostRates();

// Seconds as the budget's messages write them: "0.3", "12", "5400".
std::string formatSeconds(double seconds);

}  // namespace facetlight::server
