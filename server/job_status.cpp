#include "job_status.h"

#include <algorithm>
#include <cmath>

#include "study/job_progress.h"
#include "study/result_files.h"

namespace facetlight::server {
namespace {

using nlohmann::json;

json nullIfEmpty(const std::string& s) {
    return s.empty() ? json(nullptr) : json(s);
}

json progressJson(const JobProgress& p) {
    json j = {{"phase", p.phase}, {"done", p.done},   {"total", p.total},    {"fraction", p.fraction},
              {"step", p.step},   {"steps", p.steps}, {"overall", p.overall}};
    if (p.sweep) {
        j["points_done"] = p.pointsDone;
        j["points_total"] = p.pointsTotal;
    }
    return j;
}

// A stored job that no longer reads as one (it fails if run) is shown with a default job's steps.
const JobRequest& specOf(const JobRecord& job) {
    static const JobRequest unread;
    return job.spec ? *job.spec : unread;
}

}  // namespace

std::string jobPath(const std::string& id) {
    return "/api/jobs/" + id;
}

json jobStatusJson(const JobRecord& job, const JobQueue& queue) {
    const std::string self = jobPath(job.id);
    const JobRequest& spec = specOf(job);
    const int requested = spec.settings.trace.threads;
    json threads = {{"requested", requested}, {"cores", queue.cores()}};
    const int used = job.threadsUsed > 0 ? job.threadsUsed : std::min(requested, queue.cores());
    threads["used"] = used;
    if (used < requested) {
        threads["note"] = "capped at the " + std::to_string(queue.cores()) + " cores of this machine";
    }
    JobProgress progress = idleProgress(spec.settings, std::string(jobStateName(job.state)));
    json doc = {{"id", job.id},
                {"state", jobStateName(job.state)},
                {"mesh", spec.mesh},
                {"name", spec.name.empty() ? spec.mesh : spec.name},
                {"settings", job.request},
                {"created_at", job.createdAt},
                {"started_at", nullIfEmpty(job.startedAt)},
                {"finished_at", nullIfEmpty(job.finishedAt)},
                {"threads", threads}};
    // This server's estimate of the whole job with the threads it gets (job_budget.h); none for a stored job
    // that no longer reads.
    if (job.spec)
        doc["estimate_s"] = std::round(queue.budget().estimate(spec.settings, used).seconds * 100) / 100;
    json links = {{"self", self}};
    switch (job.state) {
        case JobState::Queued:
            if (const auto pos = queue.queuePosition(job.id)) doc["queue_position"] = *pos;
            links["cancel"] = self + "/cancel";
            break;
        case JobState::Running:
            if (const auto live = queue.live(job.id)) {
                progress = runningProgress(spec.settings, *live);
                doc["cancel_requested"] = live->cancelled();
            }
            links["cancel"] = self + "/cancel";
            break;
        case JobState::Succeeded:
            progress = finishedProgress(spec.settings);
            for (const ResultFile& f : kResultFiles)
                if (hasResultFile(f, job.request))
                    links[std::string(f.link)] = self + "/" + std::string(f.route);
            break;
        case JobState::Failed:
            doc["error"] = job.error;
            break;
        case JobState::Canceled:
            break;
    }
    if (progress.sweep) links["points"] = self + "/points";
    doc["progress"] = progressJson(progress);
    doc["links"] = links;
    return doc;
}

}  // namespace facetlight::server
