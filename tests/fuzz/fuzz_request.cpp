// libFuzzer entry point for the checks every request passes before its route (server/request_guard.h): the
// input is a request head, "METHOD PATH" then "Name: value" lines, as httplib hands it over. Any refusal is
// a fine answer; a crash, a sanitizer report or a refusal without a status in 400-499 is a finding, and so is
// an /api request let through by a server with a token without carrying it.
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "bearer_token.h"
#include "request_guard.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace facetlight::server;
    static const RequestRules rules{
        {{"GET", "/healthz"},
         {"GET", "/api/jobs"},
         {"POST", "/api/jobs"},
         {"GET", "/api/jobs/{id}"},
         {"DELETE", "/api/jobs/{id}"},
         {"POST", "/api/jobs/{id}/cancel"},
         {"GET", "/api/jobs/{id}/stats.csv"},
         {"POST", "/api/meshes"}},
        256,
        [](const std::string& path) { return path == "/api/meshes" ? 4096 : 1024; },
        {{"POST /api/jobs", {"application/json"}},
         {"POST /api/meshes", {"application/octet-stream", "multipart/form-data"}}}};
    std::string_view text(reinterpret_cast<const char*>(data), size);
    httplib::Request req;
    for (bool first = true; !text.empty(); first = false) {
        const size_t end = std::min(text.find('\n'), text.size());
        const std::string_view line = text.substr(0, end);
        text.remove_prefix(std::min(end + 1, text.size()));
        if (first) {
            const size_t space = std::min(line.find(' '), line.size());
            req.method = line.substr(0, space);
            req.path = req.target = line.substr(std::min(space + 1, line.size()));
        } else if (const size_t colon = line.find(':'); colon != std::string_view::npos) {
            req.headers.emplace(std::string(line.substr(0, colon)), std::string(line.substr(colon + 1)));
        }
    }
    if (const auto refusal = checkRequest(req, rules);
        refusal && (refusal->status < 400 || refusal->status > 499))
        std::abort();
    static const RequestRules withToken = [] {
        RequestRules r = rules;
        r.token = "fuzz-token-0123456789";
        return r;
    }();
    const auto refusal = checkRequest(req, withToken);
    if (refusal && (refusal->status < 400 || refusal->status > 499)) std::abort();
    if (!refusal && (req.path == "/api" || req.path.starts_with("/api/")) &&
        !bearerMatches(req.get_header_value("Authorization"), withToken.token))
        std::abort();
    if (escapeForLog(req.path).find_first_of("\n\r\"") != std::string::npos) std::abort();
    return 0;
}
