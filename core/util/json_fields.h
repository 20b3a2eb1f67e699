#pragma once
// Strict readers for the fields of untrusted settings JSON (jobs sent to the service, job files): a wrong
// type or an out-of-range value throws Error naming the field by its dotted path, e.g. "render.width".
#include <cstdint>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "geometry/geometry.h"

namespace facetlight::json_fields {

// Refuses a non-object and any key not in `known`. `path` is the object's dotted path ("" at the top).
void checkKeys(const nlohmann::json& j, const std::string& path, const std::set<std::string>& known);
// A whole number in [lo, hi]; 1e6 written as a float is accepted.
uint64_t getCount(const nlohmann::json& j, const std::string& field, uint64_t lo, uint64_t hi);
double getNumber(const nlohmann::json& j, const std::string& field);
bool getBool(const nlohmann::json& j, const std::string& field);
std::string getString(const nlohmann::json& j, const std::string& field);
Vec3 getVec3(const nlohmann::json& j, const std::string& field);

}  // namespace facetlight::json_fields
