#include "problem.h"

#include <iostream>

#include "util/excerpt.h"

namespace facetlight::server {

std::string_view reasonPhrase(int status) {
    switch (status) {
        case 400:
            return "Bad Request";
        case 401:
            return "Unauthorized";
        case 403:
            return "Forbidden";
        case 404:
            return "Not Found";
        case 405:
            return "Method Not Allowed";
        case 409:
            return "Conflict";
        case 411:
            return "Length Required";
        case 413:
            return "Payload Too Large";
        case 414:
            return "URI Too Long";
        case 415:
            return "Unsupported Media Type";
        case 416:
            return "Range Not Satisfiable";
        case 421:
            return "Misdirected Request";
        case 422:
            return "Unprocessable Content";
        case 431:
            return "Request Header Fields Too Large";
        case 500:
            return "Internal Server Error";
        case 503:
            return "Service Unavailable";
        case 507:
            return "Insufficient Storage";
        default:
            return status >= 500 ? "Server Error" : "Client Error";
    }
}

// Whatever a message quotes, a problem stays short and valid JSON (issue 31): the excerpts are the backstop
// of the quoting in the messages, the replacement of bytes that are not UTF-8 that of the readers.
void problem(httplib::Response& res, int status, const std::string& detail, const std::string& field) {
    nlohmann::json body = {{"type", "about:blank"},
                           {"title", reasonPhrase(status)},
                           {"status", status},
                           {"detail", excerpt(detail, kMaxDetailBytes)}};
    if (!field.empty()) body["field"] = excerpt(field, kMaxFieldBytes);
    res.status = status;
    res.set_content(body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace), kProblemType);
}

void sendJson(httplib::Response& res, int status, const nlohmann::json& body) {
    res.status = status;
    res.set_content(body.dump(2) + "\n", kJsonType);
}

void storageProblem(httplib::Response& res, const StorageError& e, uint64_t freeBytes) {
    std::cerr << "facetlight-server: storage: " << e.what() << "\n";
    res.set_header("Retry-After", "60");
    if (e.full() || freeBytes == 0)
        return problem(
            res, 507,
            "the server's storage is full: nothing was stored; try again once space is freed, e.g. by "
            "deleting finished jobs");
    problem(res, 503, "the server's storage is failing: nothing was stored; the server log has the details");
}

}  // namespace facetlight::server
