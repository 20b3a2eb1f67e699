#include <algorithm>

#include <gtest/gtest.h>

#include "request_guard.h"

using namespace facetlight::server;

namespace {

const RequestRules& rules() {
    static const RequestRules r{{{"GET", "/healthz"},
                                 {"GET", "/api/jobs"},
                                 {"POST", "/api/jobs"},
                                 {"GET", "/api/jobs/{id}"},
                                 {"DELETE", "/api/jobs/{id}"},
                                 {"POST", "/api/jobs/{id}/cancel"},
                                 {"POST", "/api/meshes"}},
                                100,
                                [](const std::string& path) { return path == "/api/meshes" ? 5000 : 1000; },
                                {{"POST /api/jobs", {"application/json"}},
                                 {"POST /api/meshes", {"application/octet-stream", "multipart/form-data"}}}};
    return r;
}

const std::string kId = "0123456789abcdef0123456789abcdef";
const std::string kJson = "application/json";

httplib::Request request(std::string method, std::string path,
                         std::vector<std::pair<std::string, std::string>> headers = {}) {
    httplib::Request req;
    req.method = std::move(method);
    req.path = path;
    req.target = path;
    for (auto& [k, v] : headers) req.headers.emplace(k, v);
    return req;
}

int statusOf(const httplib::Request& req) {
    const auto r = checkRequest(req, rules());
    return r ? r->status : 0;
}

}  // namespace

TEST(RequestGuard, OrdinaryRequestsPass) {
    EXPECT_EQ(statusOf(request("GET", "/healthz")), 0);
    EXPECT_EQ(statusOf(request("GET", "/api/jobs/" + kId)), 0);
    EXPECT_EQ(statusOf(request("POST", "/api/jobs", {{"Content-Length", "10"}, {"Content-Type", kJson}})), 0);
    EXPECT_EQ(statusOf(request("POST", "/api/meshes",
                               {{"Content-Length", "5000"}, {"Content-Type", "application/octet-stream"}})),
              0);
    // `curl -X POST` sends no Content-Length, and cancel takes no body.
    EXPECT_EQ(statusOf(request("POST", "/api/jobs/" + kId + "/cancel")), 0);
    EXPECT_EQ(statusOf(request("GET", "/index.html")), 0);  // not an API route: static files or 404
    // The same length twice is not a conflict.
    EXPECT_EQ(
        statusOf(request("POST", "/api/jobs",
                         {{"Content-Length", "10"}, {"content-length", "10"}, {"Content-Type", kJson}})),
        0);
}

TEST(RequestGuard, ContentLengthMustBeOneWholeNumber) {
    EXPECT_EQ(statusOf(request("POST", "/api/jobs", {{"Content-Length", "abc"}})), 400);
    EXPECT_EQ(statusOf(request("POST", "/api/jobs", {{"Content-Length", "-1"}})), 400);
    EXPECT_EQ(statusOf(request("POST", "/api/jobs", {{"Content-Length", ""}})), 400);
    EXPECT_EQ(statusOf(request("POST", "/api/jobs", {{"Content-Length", "99999999999999999999"}})), 400);
    // Request smuggling: two different lengths.
    const auto twice = checkRequest(
        request("POST", "/api/jobs", {{"Content-Length", "5"}, {"Content-Length", "50"}}), rules());
    ASSERT_TRUE(twice);
    EXPECT_EQ(twice->status, 400);
    EXPECT_EQ(twice->detail, "the request has two different Content-Length headers");
}

TEST(RequestGuard, BodiesNeedALengthWithinTheRoutesLimit) {
    EXPECT_EQ(statusOf(request("POST", "/api/jobs")), 411);
    EXPECT_EQ(statusOf(request("POST", "/api/meshes")), 411);
    EXPECT_EQ(statusOf(request("POST", "/api/jobs", {{"Transfer-Encoding", "chunked"}})), 411);
    EXPECT_EQ(statusOf(request("POST", "/api/jobs", {{"Content-Length", "1001"}})), 413);
    EXPECT_EQ(statusOf(request("POST", "/api/meshes", {{"Content-Length", "5001"}})), 413);
    EXPECT_EQ(statusOf(request("GET", "/healthz", {{"Content-Length", "1001"}})), 413);
}

TEST(RequestGuard, OnlyTheHostNamesWeAreReachedBy) {
    for (const char* host :
         {"localhost", "LocalHost:8080", "127.0.0.1", "127.0.0.1:1", "[::1]", "[::1]:65535"})
        EXPECT_EQ(statusOf(request("GET", "/api/jobs", {{"Host", host}})), 0) << host;
    // DNS rebinding: a page on evil.example whose name now resolves to 127.0.0.1.
    for (const char* host : {"evil.example", "evil.example:8080", "localhost.evil.example", "127.0.0.1:x",
                             "127.0.0.1:", "::1", "", "localhost:8080:8080"})
        EXPECT_EQ(statusOf(request("GET", "/api/jobs", {{"Host", host}})), 421) << host;
    EXPECT_EQ(statusOf(request("GET", "/index.html", {{"Host", "evil.example"}})), 421);  // the page too
    httplib::Request noHost = request("GET", "/healthz");
    noHost.version = "HTTP/1.0";
    EXPECT_EQ(statusOf(noHost), 0);
    noHost.version = "HTTP/1.1";
    EXPECT_EQ(statusOf(noHost), 400);
    RequestRules more = rules();
    more.allowedHosts.insert("gems.example");
    EXPECT_FALSE(checkRequest(request("GET", "/healthz", {{"Host", "Gems.Example:443"}}), more));
}

TEST(RequestGuard, ChangesOnlyFromOurOrigins) {
    const auto post = [](const std::string& origin) {
        return statusOf(request("POST", "/api/jobs",
                                {{"Content-Length", "10"}, {"Content-Type", kJson}, {"Origin", origin}}));
    };
    EXPECT_EQ(post("http://localhost:8080"), 0);
    EXPECT_EQ(post("https://127.0.0.1"), 0);
    EXPECT_EQ(post("http://evil.example"), 403);
    EXPECT_EQ(post("http://localhost.evil.example"), 403);
    EXPECT_EQ(post("null"), 403);
    EXPECT_EQ(post("ftp://localhost"), 403);
    EXPECT_EQ(statusOf(request("DELETE", "/api/jobs/" + kId, {{"Origin", "http://evil.example"}})), 403);
    EXPECT_EQ(statusOf(request("POST", "/api/jobs/" + kId + "/cancel", {{"Origin", "http://evil.example"}})),
              403);
    // Reading is not a change: a browser keeps another site's page from reading the answer.
    EXPECT_EQ(statusOf(request("GET", "/api/jobs", {{"Origin", "http://evil.example"}})), 0);
}

TEST(RequestGuard, BodiesOfOurOwnMediaTypes) {
    const auto post = [](const std::string& path, const std::string& type) {
        std::vector<std::pair<std::string, std::string>> headers = {{"Content-Length", "10"}};
        if (!type.empty()) headers.emplace_back("Content-Type", type);
        return statusOf(request("POST", path, headers));
    };
    EXPECT_EQ(post("/api/jobs", "Application/JSON; charset=utf-8"), 0);
    // What a form on any site sends without a preflight.
    for (const char* type : {"text/plain", "application/x-www-form-urlencoded", "multipart/form-data", ""})
        EXPECT_EQ(post("/api/jobs", type), 415) << type;
    EXPECT_EQ(post("/api/meshes", "multipart/form-data; boundary=x"), 0);
    EXPECT_EQ(post("/api/meshes", "application/octet-stream"), 0);
    EXPECT_EQ(post("/api/meshes", "text/plain"), 415);
    EXPECT_EQ(post("/api/meshes", ""), 415);
    // Cancel takes no body.
    EXPECT_EQ(statusOf(request("POST", "/api/jobs/" + kId + "/cancel", {{"Content-Type", "text/plain"}})), 0);
}

TEST(RequestGuard, WrongMethodIs405WithAllow) {
    const auto r = checkRequest(request("PUT", "/api/jobs/" + kId), rules());
    ASSERT_TRUE(r);
    EXPECT_EQ(r->status, 405);
    ASSERT_FALSE(r->headers.empty());
    EXPECT_EQ(r->headers[0], (std::pair<std::string, std::string>{"Allow", "DELETE, GET, HEAD"}));
    EXPECT_EQ(statusOf(request("POST", "/healthz")), 405);
    EXPECT_EQ(statusOf(request("DELETE", "/api/jobs")), 405);
    EXPECT_EQ(statusOf(request("GET", "/api/jobs/" + kId + "/cancel")), 405);
    EXPECT_EQ(statusOf(request("HEAD", "/healthz")), 0);
    EXPECT_EQ(methodsAllowed(rules().routes, "/api/jobs/not-an-id"), std::vector<std::string>{});
    EXPECT_EQ(methodsAllowed(rules().routes, "/api/jobs/" + kId + "/cancel/x"), std::vector<std::string>{});
}

TEST(RequestGuard, PathsWithControlCharactersOrTooLongAreRefused) {
    EXPECT_EQ(statusOf(request("GET", std::string("/index.html\0.js", 15))), 400);
    EXPECT_EQ(statusOf(request("GET", "/api/jobs\n200 OK")), 400);
    EXPECT_EQ(statusOf(request("GET", "/" + std::string(100, 'a'))), 414);
}

TEST(RequestGuard, LogLinesCannotBeForged) {
    EXPECT_EQ(escapeForLog("/api/jobs\n2026-01-01 127.0.0.1 \"GET /\" 200"),
              "/api/jobs\\x0a2026-01-01 127.0.0.1 \\x22GET /\\x22 200");
    EXPECT_EQ(escapeForLog(std::string("a\0b", 3)), "a\\x00b");
    EXPECT_EQ(escapeForLog("\xc3\xa9"), "\\xc3\\xa9");
    EXPECT_EQ(escapeForLog(std::string(300, 'a'), 200), std::string(200, 'a') + "...");
}

// Issue 31, item 1: with a token, every /api request carries it; /healthz and the page do not need it.
TEST(RequestGuard, ApiRequestsCarryTheBearerToken) {
    RequestRules withToken = rules();
    withToken.token = "s3cret-token-0123456789";
    const auto check = [&](const std::string& method, const std::string& path, const std::string& auth) {
        std::vector<std::pair<std::string, std::string>> headers;
        if (!auth.empty()) headers.emplace_back("Authorization", auth);
        return checkRequest(request(method, path, headers), withToken);
    };
    for (const std::string& path :
         std::vector<std::string>{"/api/jobs", "/api/jobs/" + kId, "/api/jobs/" + kId + "/render.png",
                                  "/api/openapi.json", "/api/nothing-here", "/api"}) {
        const auto none = check("GET", path, "");
        ASSERT_TRUE(none) << path;
        EXPECT_EQ(none->status, 401) << path;
        EXPECT_NE(
            std::find(none->headers.begin(), none->headers.end(),
                      std::pair<std::string, std::string>{"WWW-Authenticate", "Bearer realm=\"facetlight\""}),
            none->headers.end());
        EXPECT_FALSE(check("GET", path, "Bearer s3cret-token-0123456789")) << path;
    }
    EXPECT_FALSE(check("GET", "/api/jobs", "bearer  s3cret-token-0123456789 "));  // the scheme in any case
    for (const char* wrong : {"Bearer s3cret-token-012345678", "Bearer s3cret-token-01234567890",
                              "Bearer S3cret-token-0123456789", "Basic s3cret-token-0123456789",
                              "s3cret-token-0123456789", "Bearer", "Bearer "}) {
        const auto r = check("GET", "/api/jobs", wrong);
        ASSERT_TRUE(r) << wrong;
        EXPECT_EQ(r->status, 401) << wrong;
    }
    EXPECT_EQ(check("DELETE", "/api/jobs/" + kId, "")->status, 401);
    EXPECT_FALSE(check("GET", "/healthz", ""));
    EXPECT_FALSE(check("GET", "/index.html", ""));
    EXPECT_FALSE(check("GET", "/apis.js", ""));
    // Without a token nothing is asked.
    EXPECT_EQ(statusOf(request("GET", "/api/jobs")), 0);
}
