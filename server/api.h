#pragma once
// The HTTP face of the service: the routes and their handlers, the guards before them, the error handlers and
// the access log. Answers are written with problem.h (problem+json, RFC 9457), a job's status with
// job_status.h, bodies read with request_body.h. Handlers only read and write the store and the queue; jobs
// run on the queue's worker.
#include <optional>
#include <set>
#include <shared_mutex>
#include <string>
#include <string_view>
#include <vector>

#include <httplib.h>

#include "job_queue.h"
#include "job_spec.h"
#include "job_store.h"
#include "mesh_catalog.h"
#include "request_guard.h"
#include "result_store.h"

namespace facetlight::server {

// The OpenAPI 3 description of the routes below, embedded at build time from server/openapi.json.
std::string_view openApiDocument();

class Api {
  public:
    // `readOnly`: why the store cannot be written (empty: it can); then every route that writes answers 503.
    // `allowedHosts`: names the server is reached by besides the loopback ones (RequestRules::allowedHosts);
    // `token`: the bearer token /api requests must carry (empty: none, RequestRules::token).
    Api(ResultStore& results, JobQueue& queue, MeshCatalog& catalog, ServiceLimits limits,
        std::string readOnly, const std::vector<std::string>& allowedHosts, std::string token);
    // Registers every route, the guards that run before them, the error handlers and the access log.
    void install(httplib::Server& server, bool accessLog);
    static std::vector<Route> routes();

  private:
    bool refuseWhenStorageLow(httplib::Response& res) const;  // true: answered 507
    bool refuseWhenReadOnly(httplib::Response& res) const;    // true: answered 503
    // `writable`: false when nothing can be written (the disk has no room, or the store refuses writes).
    nlohmann::json storageJson(bool& writable) const;
    // A job's body checked as a submission is, before anything is stored: 400 for a body that is not a JSON
    // object, 422 naming the field at fault (a setting, the mesh, the light; the budget when
    // `enforceBudget`). Nothing when `res` holds the refusal. The caller holds meshUse_ shared.
    std::optional<JobRequest> checkJob(const std::string& body, httplib::Response& res, bool enforceBudget);
    void submitJob(const httplib::Request& req, httplib::Response& res, const httplib::ContentReader& reader);
    void estimateJob(const httplib::Request& req, httplib::Response& res,
                     const httplib::ContentReader& reader);
    void uploadMesh(const httplib::Request& req, httplib::Response& res,
                    const httplib::ContentReader& reader);
    void listJobs(const httplib::Request& req, httplib::Response& res);
    void getJob(const httplib::Request& req, httplib::Response& res);
    void cancelJob(const httplib::Request& req, httplib::Response& res);
    void deleteJob(const httplib::Request& req, httplib::Response& res);
    void deleteMesh(const httplib::Request& req, httplib::Response& res);
    void getSweepPoints(const httplib::Request& req, httplib::Response& res);
    void getResult(const httplib::Request& req, httplib::Response& res, const std::string& file,
                   const std::string& contentType);

    ResultStore& results_;
    JobQueue& queue_;
    MeshCatalog& catalog_;
    ServiceLimits limits_;
    std::string readOnly_;
    std::set<std::string> allowedHosts_;
    std::string token_;
    // Held shared by a submission from naming its mesh until it is queued, and alone by a mesh's deletion
    // from its check that no job uses it until it is gone: no job is queued on a mesh being deleted.
    std::shared_mutex meshUse_;
};

}  // namespace facetlight::server
