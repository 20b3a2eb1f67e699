#include "api.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <utility>

#include "colour_tables.h"
#include "http_server.h"
#include "job_status.h"
#include "optics/light_model.h"
#include "problem.h"
#include "request_body.h"
#include "stats/facet_stats.h"
#include "study/result_files.h"
#include "sweep/sweep_references.h"
#include "sweep/sweep_request.h"
#include "util/error.h"
#include "util/json_text.h"
#include "util/simd_target.h"

namespace facetlight::server {
namespace {

using httplib::Request;
using httplib::Response;
using nlohmann::json;

// cpp-httplib 0.11 cuts whatever body is answered to the request's Range: a problem's, a job list's. Only
// result files are served in ranges, so the guard clears them elsewhere and getResult() on its problems. The
// Request is httplib's own, not const: its handlers only see it so.
httplib::Ranges& withRanges(const Request& req) {
    return const_cast<Request&>(req).ranges;
}

void logRequest(const Request& req, const Response& res) {
    const std::string line = nowIso8601() + " " + req.remote_addr + " \"" + escapeForLog(req.method, 16) +
                             " " + escapeForLog(req.path) + "\" " + std::to_string(res.status) + " " +
                             std::to_string(res.body.size()) + "\n";
    std::fputs(line.c_str(), stderr);
}

}  // namespace

Api::Api(ResultStore& results, JobQueue& queue, MeshCatalog& catalog, ServiceLimits limits,
         std::string readOnly, const std::vector<std::string>& allowedHosts, std::string token)
    : results_(results),
      queue_(queue),
      catalog_(catalog),
      limits_(limits),
      readOnly_(std::move(readOnly)),
      allowedHosts_(allowedHosts.begin(), allowedHosts.end()),
      token_(std::move(token)) {}

std::vector<Route> Api::routes() {
    std::vector<Route> routes = {
        {"GET", "/healthz"},
        {"GET", "/api/openapi.json"},
        {"GET", "/api/defaults"},
        {"GET", "/api/colour/cie"},
        {"GET", "/api/colour/by-transmission"},
        {"GET", "/api/jobs"},
        {"POST", "/api/jobs"},
        {"POST", "/api/jobs/estimate"},
        {"GET", "/api/jobs/{id}"},
        {"DELETE", "/api/jobs/{id}"},
        {"POST", "/api/jobs/{id}/cancel"},
        {"GET", "/api/jobs/{id}/points"},
    };
    for (const ResultFile& f : kResultFiles)
        routes.push_back({"GET", "/api/jobs/{id}/" + std::string(f.route)});
    routes.push_back({"GET", "/api/meshes"});
    routes.push_back({"POST", "/api/meshes"});
    routes.push_back({"DELETE", "/api/meshes/{id}"});
    return routes;
}

// New work stops before the disk fills: jobs and uploads would fail half-written, and a full disk kept
// finished jobs from being deleted (issue 18). Status, results, cancel and delete go on.
bool Api::refuseWhenStorageLow(Response& res) const {
    if (refuseWhenReadOnly(res)) return true;
    const std::string shortage = results_.spaceShortage(limits_.minFreeBytes);
    if (shortage.empty()) return false;
    res.set_header("Retry-After", "60");
    problem(res, 507, shortage + ": no new work until space is freed, e.g. by deleting finished jobs");
    return true;
}

// A store on a read-only disk serves what it holds and changes nothing.
bool Api::refuseWhenReadOnly(Response& res) const {
    if (readOnly_.empty()) return false;
    res.set_header("Retry-After", "300");
    problem(
        res, 503,
        "the server's storage is read-only (" + readOnly_ + "): jobs and meshes can be read, not changed");
    return true;
}

// For /healthz: whether the store takes new work, and why not. A disk without one free byte, or one that
// refuses a probe's byte, is full whatever --min-free says (with --min-free 0 it was "ok"): then, and while
// the store refuses writes, nothing the service does can be kept, and /healthz answers 503.
json Api::storageJson(bool& writable) const {
    const uint64_t free = results_.freeBytes();
    std::string state = "ok", detail;
    writable = true;
    if (!readOnly_.empty()) {
        state = "read-only";
        detail = "the store is read-only (" + readOnly_ + "): no jobs run or are accepted";
    } else if (const size_t unsaved = queue_.unsavedCount()) {
        state = "failing";
        detail = std::to_string(unsaved) + " job state(s) not yet recorded: the store refused writes";
        writable = false;
    } else if (const std::string refusal =
                   free == 0 ? "the server's storage has no free byte" : results_.writeRefusal();
               !refusal.empty()) {
        state = "full";
        detail = refusal + ": nothing can be stored; new jobs and uploads get 507, queued jobs fail";
        writable = false;
    } else if (const std::string shortage = results_.spaceShortage(limits_.minFreeBytes); !shortage.empty()) {
        state = "full";
        detail = shortage + ": new jobs and uploads get 507, queued jobs fail";
    }
    json doc = {{"state", state}, {"free_bytes", free}, {"min_free_bytes", limits_.minFreeBytes}};
    if (!detail.empty()) doc["detail"] = detail;
    return doc;
}

std::optional<JobRequest> Api::checkJob(const std::string& body, Response& res, bool enforceBudget) {
    json j;
    try {
        j = parseUntrustedJson(body, "the body");
    } catch (const Error& e) {
        problem(res, 400, e.what());
        return std::nullopt;
    }
    if (!j.is_object()) {
        problem(res, 400, "the job must be a JSON object");
        return std::nullopt;
    }
    JobRequest spec;
    try {
        spec = parseJobSpec(j, queue_.cores(), &limits_);
        // Before anything is built or stored: a job that would hold the worker too long (issue 31).
        if (enforceBudget) queue_.budget().check(spec.settings, queue_.threadsFor(spec));
    } catch (const Error& e) {
        problem(res, 422, e.what(), e.field());
        return std::nullopt;
    }
    // A sweep's shape, and a design's (cut), were checked with them; the stone a job traces is built here, so
    // that what depends on it (a point light outside it) is refused now, not when the job runs.
    std::shared_ptr<const Stone> stone;
    try {
        // A sweep of a design or mesh file: its tiers and the request are checked once the file is found.
        if (spec.settings.sweep && !isLibraryShape(spec.mesh))
            planSweepOf(catalog_.shapeSource(spec.mesh), *spec.settings.sweep, spec.settings.trace,
                        spec.settings.colour);
        if (!spec.settings.sweep)
            stone = spec.cut.empty() ? catalog_.resolve(spec.mesh)
                                     : std::make_shared<const Stone>(cutStone(spec, catalog_.shapeSource(spec.mesh)));
    } catch (const Error& e) {
        problem(res, 422, e.what(), e.field().empty() ? "mesh" : e.field());
        return std::nullopt;
    }
    try {
        if (stone) LightModel(spec.settings.trace.light, *stone);
    } catch (const Error& e) {
        problem(res, 422, e.what(), e.field().empty() ? "light" : e.field());
        return std::nullopt;
    }
    return spec;
}

void Api::submitJob(const Request& req, Response& res, const httplib::ContentReader& reader) {
    BodyCollector body(limits_, req);
    body.read(reader);
    if (body.refuseIncomplete(res, "the job")) return;
    if (refuseWhenStorageLow(res)) return;
    std::shared_lock meshInUse(meshUse_);  // until the job is queued
    std::optional<JobRequest> checked = checkJob(body.bytes(), res, true);
    if (!checked) return;
    JobRequest& spec = *checked;
    // Named here, where an upload's file name is known, so that the API and the page show one name.
    if (spec.name.empty()) spec.name = defaultJobName(spec, catalog_.designName(spec.mesh));
    JobRecord job;
    job.id = newId();
    job.spec = std::make_shared<const JobRequest>(std::move(spec));  // the one parse of this job
    job.request = toJson(*job.spec);
    job.createdAt = nowIso8601();
    bool queued;
    try {
        queued = queue_.submit(job);
    } catch (const StorageError& e) {
        return storageProblem(res, e, results_.freeBytes());
    }
    if (!queued) {
        res.set_header("Retry-After", "30");
        return problem(res, 503,
                       "the queue is full (" + std::to_string(limits_.maxQueued) + " jobs); try again later");
    }
    res.set_header("Location", jobPath(job.id));
    sendJson(res, 202, jobStatusJson(job, queue_));
}

// What a job would cost here, checked as a submission is but neither queued nor stored: the page shows it as
// the form is edited, and a client learns whether the job would be refused before sending it.
void Api::estimateJob(const Request& req, Response& res, const httplib::ContentReader& reader) {
    BodyCollector body(limits_, req);
    body.read(reader);
    if (body.refuseIncomplete(res, "the job")) return;
    std::optional<JobRequest> spec;
    {
        std::shared_lock meshInUse(meshUse_);
        spec = checkJob(body.bytes(), res, false);
    }
    if (!spec) return;
    const JobBudget& budget = queue_.budget();
    const int threads = queue_.threadsFor(*spec);
    const JobCost cost = budget.estimate(spec->settings, threads);
    const auto seconds = [](double s) { return std::round(s * 100) / 100; };
    const auto partJson = [&](const CostPart& part) {
        json doc = {{"part", part.name}, {"size", part.size}, {"seconds", seconds(part.seconds)}};
        if (!part.field.empty()) doc["field"] = part.field;
        return doc;
    };
    json parts = json::array();
    for (const CostPart& part : cost.parts) parts.push_back(partJson(part));
    const std::string refusal = budget.refusal(cost, threads);
    json doc = {{"estimate_s", seconds(cost.seconds)},
                {"threads", threads},
                {"max_job_seconds", budget.maxSeconds()},
                {"largest", partJson(cost.largest())},
                {"parts", std::move(parts)},
                {"refused", !refusal.empty()}};
    if (!refusal.empty()) doc["reason"] = refusal;
    sendJson(res, 200, doc);
}

void Api::uploadMesh(const Request& req, Response& res, const httplib::ContentReader& reader) {
    std::string fileName = req.has_param("name") ? req.get_param_value("name") : "upload";
    BodyCollector body(limits_, req);
    int files = 0;
    if (req.is_multipart_form_data()) {
        // cpp-httplib reads a multipart body without a boundary as one that ended early: say what is missing.
        if (req.get_header_value("Content-Type").find("boundary=") == std::string::npos)
            return problem(res, 400,
                           "a multipart/form-data upload needs its boundary: Content-Type: "
                           "multipart/form-data; boundary=...",
                           "Content-Type");
        // The first part named "file" is the mesh; other parts are read and dropped.
        bool inFile = false;
        body.readMultipart(
            reader,
            [&](const httplib::MultipartFormData& part) {
                inFile = part.name == "file" && ++files == 1;
                if (inFile && !part.filename.empty()) fileName = part.filename;
                return true;
            },
            [&] { return inFile; });
    } else {
        body.read(reader);
    }
    if (body.refuseIncomplete(res, "the upload")) return;
    if (req.is_multipart_form_data() && files == 0)
        return problem(res, 422, "a multipart upload carries the mesh in a part named \"file\"", "file");
    if (refuseWhenStorageLow(res)) return;
    std::optional<MeshFormat> format;
    if (req.has_param("format")) {
        format = parseMeshFormat(req.get_param_value("format"));
        if (!format) return problem(res, 422, "format must be one of obj, stl, asc, gem", "format");
    }
    try {
        const MeshRecord m = catalog_.upload(body.bytes(), fileName, format);
        json doc = m.summary;
        doc["mesh"] = m.id;
        doc["file_name"] = m.name;
        doc["format"] = m.format;
        doc["created_at"] = m.createdAt;
        sendJson(res, 201, doc);
    } catch (const StorageError& e) {
        storageProblem(res, e, results_.freeBytes());
    } catch (const MeshStoreFull& e) {
        problem(res, 507, e.what(), "file");
    } catch (const Error& e) {
        problem(res, 422, std::string("the mesh was refused: ") + e.what(), "file");
    }
}

void Api::deleteMesh(const Request& req, Response& res) {
    const std::string id = req.matches[1];
    std::unique_lock meshInUse(meshUse_);
    if (!catalog_.isUploaded(id)) return problem(res, 404, "no uploaded mesh with this id");
    if (queue_.usesMesh(id))
        return problem(res, 409, "a queued or running job uses this mesh: cancel it, or wait until it ends");
    if (refuseWhenReadOnly(res)) return;
    try {
        if (!catalog_.remove(id)) return problem(res, 404, "no uploaded mesh with this id");
    } catch (const StorageError& e) {
        return storageProblem(res, e, results_.freeBytes());
    }
    res.status = 204;
}

void Api::listJobs(const Request& req, Response& res) {
    int64_t limit, offset;
    try {
        limit = queryInt(req, "limit", 20, 1, 100);
        offset = queryInt(req, "offset", 0, 0, 1'000'000'000);
    } catch (const Error& e) {
        return problem(res, 400, e.what(), e.field());
    }
    // Bounded in bytes as well as in jobs: at least one job, then as many as fit (issue 31).
    json jobs = json::array();
    size_t bytes = 0;
    for (const auto& job : queue_.jobs(int(limit), int(offset))) {
        json status = jobStatusJson(job, queue_);
        bytes += status.dump().size();
        if (!jobs.empty() && bytes > limits_.maxListBytes) break;
        jobs.push_back(std::move(status));
    }
    const int64_t total = queue_.jobCount(), after = offset + int64_t(jobs.size());
    json doc = {{"jobs", jobs}, {"total", total}, {"limit", limit}, {"offset", offset}, {"next", nullptr}};
    if (after < total)
        doc["next"] = "/api/jobs?limit=" + std::to_string(limit) + "&offset=" + std::to_string(after);
    sendJson(res, 200, doc);
}

void Api::getJob(const Request& req, Response& res) {
    const auto job = queue_.job(req.matches[1]);
    if (!job) return problem(res, 404, "no job with this id");
    sendJson(res, 200, jobStatusJson(*job, queue_));
}

void Api::cancelJob(const Request& req, Response& res) {
    const std::string id = req.matches[1];
    const auto job = queue_.job(id);
    if (!job) return problem(res, 404, "no job with this id");
    if (job->state == JobState::Succeeded || job->state == JobState::Failed) {
        return problem(res, 409, "the job has already " + std::string(jobStateName(job->state)));
    }
    if (refuseWhenReadOnly(res)) return;
    const auto outcome = queue_.cancel(id);
    const auto now = queue_.job(id);
    if (!now) return problem(res, 404, "no job with this id");
    sendJson(res, outcome == JobQueue::CancelOutcome::Requested ? 202 : 200, jobStatusJson(*now, queue_));
}

void Api::deleteJob(const Request& req, Response& res) {
    const std::string id = req.matches[1];
    const auto job = queue_.job(id);
    if (!job) return problem(res, 404, "no job with this id");
    if (!isFinished(job->state)) {
        return problem(res, 409, "the job is " + std::string(jobStateName(job->state)) + ": cancel it first");
    }
    if (refuseWhenReadOnly(res)) return;
    if (!queue_.remove(id)) return problem(res, 404, "no job with this id");
    res.status = 204;
}

void Api::getResult(const Request& req, Response& res, const std::string& file,
                    const std::string& contentType) {
    httplib::Ranges ranges = std::exchange(withRanges(req), {});  // none on a problem
    const std::string id = req.matches[1];
    const auto job = queue_.job(id);
    if (!job) return problem(res, 404, "no job with this id");
    if (job->state != JobState::Succeeded) {
        return problem(
            res, 409,
            "the job is " + std::string(jobStateName(job->state)) + "; results exist once it has succeeded");
    }
    auto bytes = results_.read(id, file);
    if (!bytes) return problem(res, 404, "this job has no " + file + " (was render false?)");
    if (file == "stats.json") {
        json stats = json::parse(*bytes);
        addShareStandardErrors(stats);
        *bytes = stats.dump(2);
    }
    // One range is given back to cpp-httplib, which answers 206 with it; one past the end is 416 here (0.11
    // answered an empty 416 under the file's type and a wrong Content-Range); several get the whole file, as
    // RFC 9110 allows.
    if (ranges.size() == 1) {
        const auto [first, last] = ranges[0];
        if (first >= 0 ? size_t(first) >= bytes->size() : last <= 0 || bytes->empty()) {
            res.set_header("Content-Range", "bytes */" + std::to_string(bytes->size()));
            return problem(
                res, 416,
                "the range lies outside the file, which has " + std::to_string(bytes->size()) + " bytes",
                "Range");
        }
        withRanges(req) = std::move(ranges);
    }
    res.set_content(std::move(*bytes), contentType.c_str());
}

// A sweep's points finished so far (those of its grid, the search's first round), for a chart that fills in
// as they finish: from the files the running sweep keeps, or from sweep.json once it has succeeded.
void Api::getSweepPoints(const Request& req, Response& res) {
    const std::string id = req.matches[1];
    const auto job = queue_.job(id);
    if (!job) return problem(res, 404, "no job with this id");
    const std::string unread = "the stored job no longer reads: ";
    if (!job->spec) return problem(res, 500, unread + job->specError);
    const JobRequest& study = *job->spec;
    if (!study.settings.sweep) return problem(res, 404, "this job is not a sweep");
    SweepPlan spec;
    try {
        spec = planSweepOf(catalog_.shapeSource(study.mesh), *study.settings.sweep, study.settings.trace,
                           study.settings.colour);
    } catch (const Error& e) {
        return problem(res, 500, unread + e.what());
    }
    json points = json::array();
    if (job->state == JobState::Succeeded) {
        if (const auto bytes = results_.read(id, "sweep.json")) points = json::parse(*bytes)["points"];
    } else {
        const std::string round0 = std::string(kSweepPointPrefix) + "0-";
        for (const std::string& name : results_.names(id, round0)) {
            if (const auto bytes = results_.read(id, name)) {
                json point = json::parse(*bytes, nullptr, false);
                if (!point.is_discarded()) points.push_back(std::move(point));
            }
        }
    }
    // The reference designs the CLI's map rings, at their values on the axes.
    json references = json::array();
    for (const SweepReference& r : sweepReferences(spec)) {
        json values = json::object();
        for (size_t a = 0; a < spec.axes.size(); ++a) values[spec.axes[a].name] = r.values[a];
        references.push_back({{"shape", r.shape}, {"label", r.label}, {"values", std::move(values)}});
    }
    sendJson(res, 200,
             {{"id", id},
              {"state", jobStateName(job->state)},
              {"shape", spec.shape},
              {"axes", sweepAxesJson(spec)},
              {"references", std::move(references)},
              {"figures", sweepFigureNames(spec.trace, spec.colour.has_value())},
              {"points_total", spec.pointCount()},
              {"points", points}});
}

void Api::install(httplib::Server& server, bool accessLog) {
    using Plain = httplib::Server::Handler;
    using WithReader = httplib::Server::HandlerWithContentReader;
    const auto result = [this](std::string file, std::string type) {
        return [this, file, type](const Request& req, Response& res) { getResult(req, res, file, type); };
    };
    std::map<std::string, Plain> plain = {
        {"GET /healthz",
         [this](const Request&, Response& res) {
             bool writable = true;
             json storage = storageJson(writable);
             sendJson(res, writable ? 200 : 503,
                      {{"status", storage["state"] == "ok" ? "ok" : "degraded"},
                       {"queued", queue_.queuedCount()},
                       {"cores", queue_.cores()},
                       {"simd", simdTarget()},
                       {"storage", std::move(storage)}});
         }},
        {"GET /api/openapi.json",
         [](const Request&, Response& res) { res.set_content(std::string(openApiDocument()), kJsonType); }},
        {"GET /api/defaults",
         [this](const Request&, Response& res) { sendJson(res, 200, jobDefaults(queue_.cores())); }},
        {"GET /api/colour/cie", [](const Request&, Response& res) { sendJson(res, 200, cieTablesJson()); }},
        {"GET /api/colour/by-transmission",
         [](const Request& req, Response& res) {
             try {
                 sendJson(res, 200, absorptionByTransmission(req.params));
             } catch (const Error& e) {
                 problem(res, 422, e.what(), e.field());
             }
         }},
        {"GET /api/jobs", [this](const Request& req, Response& res) { listJobs(req, res); }},
        {"GET /api/jobs/{id}", [this](const Request& req, Response& res) { getJob(req, res); }},
        {"DELETE /api/jobs/{id}", [this](const Request& req, Response& res) { deleteJob(req, res); }},
        {"DELETE /api/meshes/{id}", [this](const Request& req, Response& res) { deleteMesh(req, res); }},
        {"GET /api/jobs/{id}/points",
         [this](const Request& req, Response& res) { getSweepPoints(req, res); }},
        {"GET /api/meshes", [this](const Request&, Response& res) { sendJson(res, 200, catalog_.list()); }},
    };
    for (const ResultFile& f : kResultFiles)
        plain["GET /api/jobs/{id}/" + std::string(f.route)] =
            result(std::string(f.name), std::string(f.mediaType));
    // Routes that take a body read it themselves: that skips httplib's 8 KiB cap on form-encoded bodies
    // (what a plain `curl -d` sends) and lets each route count the bytes against its own limit.
    std::map<std::string, WithReader> withReader = {
        {"POST /api/jobs", [this](const Request& req, Response& res,
                                  const httplib::ContentReader& r) { submitJob(req, res, r); }},
        {"POST /api/jobs/estimate", [this](const Request& req, Response& res,
                                           const httplib::ContentReader& r) { estimateJob(req, res, r); }},
        {"POST /api/meshes", [this](const Request& req, Response& res,
                                    const httplib::ContentReader& r) { uploadMesh(req, res, r); }},
        // `curl -X POST` sends no Content-Length: a plain handler would wait out the read timeout for a body.
        {"POST /api/jobs/{id}/cancel",
         [this](const Request& req, Response& res, const httplib::ContentReader& r) {
             if (req.has_header("Content-Length")) {
                 BodyCollector ignored(limits_, req);
                 r(std::ref(ignored));
             }
             cancelJob(req, res);
         }},
    };
    for (const Route& route : routes()) {
        const std::string key = route.method + " " + route.path;
        std::string pattern = route.path;
        for (size_t at; (at = pattern.find("{id}")) != std::string::npos;)
            pattern.replace(at, 4, "([0-9a-f]{32})");
        for (size_t at = 0; (at = pattern.find('.', at)) != std::string::npos; at += 2)
            pattern.insert(at, "\\");
        if (const auto it = plain.find(key); it != plain.end()) {
            if (route.method == "GET") server.Get(pattern, it->second);
            if (route.method == "DELETE") server.Delete(pattern, it->second);
            if (route.method == "POST") server.Post(pattern, it->second);
            plain.erase(it);
        } else if (const auto w = withReader.find(key); w != withReader.end()) {
            server.Post(pattern, w->second);
            withReader.erase(w);
        } else {
            throw std::logic_error("route without a handler: " + key);
        }
    }
    if (!plain.empty() || !withReader.empty()) throw std::logic_error("handler without a route");

    const ServiceLimits limits = limits_;
    RequestRules rules{routes(),
                       limits.maxUrlBytes,
                       [limits](const std::string& path) { return bodyLimit(limits, path); },
                       {{"POST /api/jobs", {kJsonType}},
                        {"POST /api/jobs/estimate", {kJsonType}},
                        {"POST /api/meshes", {"application/octet-stream", "multipart/form-data"}}}};
    for (std::string host : allowedHosts_) {
        std::transform(host.begin(), host.end(), host.begin(),
                       [](unsigned char c) { return std::tolower(c); });
        rules.allowedHosts.insert(std::move(host));
    }
    rules.token = token_;
    server.set_payload_max_length(std::max(limits.maxBodyBytes, limits.maxUploadBytes));
    std::vector<Route> resultRoutes;
    for (const ResultFile& f : kResultFiles)
        resultRoutes.push_back({"GET", "/api/jobs/{id}/" + std::string(f.route)});
    server.set_pre_routing_handler([rules = std::move(rules), resultRoutes = std::move(resultRoutes)](
                                       const Request& req, Response& res) {
        if (methodsAllowed(resultRoutes, req.path).empty()) withRanges(req).clear();
        const auto refusal = checkRequest(req, rules);
        if (!refusal) return httplib::Server::HandlerResponse::Unhandled;
        for (const auto& [name, value] : refusal->headers) res.set_header(name, value);
        problem(res, refusal->status, refusal->detail);
        return httplib::Server::HandlerResponse::Handled;
    });
    server.set_error_handler(httplib::Server::HandlerWithResponse([](const Request&, Response& res) {
        if (!res.body.empty()) return httplib::Server::HandlerResponse::Unhandled;
        if (const HttpServer::ReadRefusal& refused = HttpServer::readRefusal(); refused.status != 0) {
            res.set_header("Connection", "close");
            problem(res, refused.status, refused.detail);
            return httplib::Server::HandlerResponse::Handled;
        }
        problem(res, res.status,
                res.status == 404 ? "no such resource (see /api/openapi.json)"
                                  : std::string(reasonPhrase(res.status)));
        return httplib::Server::HandlerResponse::Handled;
    }));
    server.set_exception_handler([](const Request& req, Response& res, std::exception_ptr ep) {
        std::string what = "unknown";
        try {
            std::rethrow_exception(ep);
        } catch (const std::exception& e) {
            what = e.what();
        } catch (...) {
        }
        std::cerr << "facetlight-server: " << req.method << " " << req.path << ": " << what << "\n";
        problem(res, 500, "internal error; the server log has the details");
    });
    if (accessLog) server.set_logger(logRequest);
}

}  // namespace facetlight::server
