#pragma once
// The service's JSON answers: a document, or a problem (RFC 9457 problem+json) titled by its status, with the
// dotted path of the request's field at fault when there is one.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include <httplib.h>
#include <nlohmann/json.hpp>

#include "database.h"

namespace facetlight::server {

constexpr const char* kProblemType = "application/problem+json";
constexpr const char* kJsonType = "application/json";

// The most bytes of a problem's detail and field: a 100 KB input quoted in either came back whole.
constexpr size_t kMaxDetailBytes = 1024;
constexpr size_t kMaxFieldBytes = 128;

std::string_view reasonPhrase(int status);
void problem(httplib::Response& res, int status, const std::string& detail, const std::string& field = {});
void sendJson(httplib::Response& res, int status, const nlohmann::json& body);

// A write the store refused: the detail (with paths) goes to the log, the client reads 507 for a full disk
// (SQLite may say only "disk I/O error": an empty disk counts too) and 503 for a failing one, without paths
// (issue 18).
void storageProblem(httplib::Response& res, const StorageError& e, uint64_t freeBytes);

}  // namespace facetlight::server
