#pragma once
// The checks every request passes before any route runs (issues 18 and 31): URL length, control characters in
// the path, the Host it was sent to and the Origin of a change (DNS rebinding, cross-site requests), the
// bearer token of an /api request, Transfer-Encoding, Content-Length (well formed, one value, within the
// route's limit, present where a body is expected), the body's media type, and methods a route does not take
// (405 with Allow). A pure function of the request, so it is unit tested and fuzzed without a server.
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <httplib.h>

namespace facetlight::server {

struct Route {
    std::string method;  // GET, POST, DELETE
    std::string path;    // as in the OpenAPI document: /api/jobs/{id}
};

struct RequestRules {
    std::vector<Route> routes;
    size_t maxUrlBytes = 2048;
    std::function<size_t(const std::string& path)> bodyLimit;  // the most bytes a body may have on a path
    // Routes that read a body ("POST /api/jobs"), with the media types it may have: they need a
    // Content-Length.
    std::map<std::string, std::set<std::string>> bodyRoutes;
    // The names the server is reached by, in lower case, without a port: a request for another Host gets 421
    // (a page on another site whose name resolves to us, DNS rebinding); a change from another Origin, 403.
    std::set<std::string> allowedHosts = {"localhost", "127.0.0.1", "[::1]"};
    // When not empty, every request under /api (result files too) must carry "Authorization: Bearer <token>",
    // else 401 with WWW-Authenticate; /healthz and the page's static files stay open.
    std::string token = {};
};

struct Refusal {
    int status = 400;
    std::string detail;
    std::vector<std::pair<std::string, std::string>> headers;  // e.g. Allow
};

// Why the request is refused, or nothing when it may go on to its route.
std::optional<Refusal> checkRequest(const httplib::Request& req, const RequestRules& rules);

// The methods of the routes whose template matches `path` ("{id}" stands for 32 hex digits), sorted; empty
// when no route has this path. HEAD comes with GET.
std::vector<std::string> methodsAllowed(const std::vector<Route>& routes, std::string_view path);

// The Content-Type without its parameters, in lower case.
std::string mediaType(const httplib::Request& req);

// `text` fit for one line of a log: control characters, quotes, backslashes and bytes above 0x7e written as
// \xNN, so that a %0a in a path cannot forge a log line; at most `maxBytes` of the input.
std::string escapeForLog(std::string_view text, size_t maxBytes = 200);

}  // namespace facetlight::server
