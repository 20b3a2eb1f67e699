#pragma once
// Reading JSON text from untrusted sources (job bodies, job files) with bounded nesting: nlohmann-json
// copies and compares values recursively, so a body nested 150 000 levels deep overflowed the stack.
#include <string_view>

#include <nlohmann/json.hpp>

namespace facetlight {

// Far above any job (settings nest 3 levels) and far below what recursion over a value can survive.
constexpr int kMaxJsonDepth = 64;

// Parses `text`, refusing it while parsing as soon as arrays and objects nest deeper than kMaxJsonDepth.
// Throws Error: "... is not valid JSON: <where>" or "... nests arrays and objects deeper than 64 levels",
// the message beginning with `what` ("the body").
nlohmann::json parseUntrustedJson(std::string_view text, const std::string& what);

}  // namespace facetlight
