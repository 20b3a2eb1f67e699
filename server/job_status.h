#pragma once
// A job as clients read it (GET /api/jobs/{id}, the list, the answers to a submit and a cancel): its record,
// the threads it got, its progress (core's JobProgress, study/job_progress.h, serialised here) and its links.
#include <string>

#include <nlohmann/json.hpp>

#include "job_queue.h"

namespace facetlight::server {

std::string jobPath(const std::string& id);  // "/api/jobs/<id>"
nlohmann::json jobStatusJson(const JobRecord& job, const JobQueue& queue);

}  // namespace facetlight::server
