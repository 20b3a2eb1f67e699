#include "util/json_fields.h"

#include <cmath>

#include "util/error.h"

namespace facetlight::json_fields {

using nlohmann::json;

void checkKeys(const json& j, const std::string& path, const std::set<std::string>& known) {
    if (!j.is_object())
        throw Error((path.empty() ? std::string("settings") : path) + " must be a JSON object");
    for (const auto& [key, value] : j.items())
        if (!known.count(key)) throw Error("unknown field '" + (path.empty() ? key : path + "." + key) + "'");
}

uint64_t getCount(const json& j, const std::string& field, uint64_t lo, uint64_t hi) {
    if (j.is_number_unsigned()) {
        const uint64_t v = j.get<uint64_t>();
        if (v >= lo && v <= hi) return v;
    } else if (j.is_number_integer()) {  // built in memory from a signed type rather than parsed
        const int64_t v = j.get<int64_t>();
        if (v >= 0 && uint64_t(v) >= lo && uint64_t(v) <= hi) return uint64_t(v);
    } else if (j.is_number_float()) {
        const double v = j.get<double>();
        // 2^64 and above do not fit (double(UINT64_MAX) rounds up to 2^64): converting them is undefined.
        if (v == std::floor(v) && v >= 0 && v < 0x1p64) {
            const uint64_t u = uint64_t(v);
            if (u >= lo && u <= hi) return u;
        }
    }
    throw Error(field + " must be an integer between " + std::to_string(lo) + " and " + std::to_string(hi));
}

double getNumber(const json& j, const std::string& field) {
    if (!j.is_number()) throw Error(field + " must be a number");
    return j.get<double>();
}

bool getBool(const json& j, const std::string& field) {
    if (!j.is_boolean()) throw Error(field + " must be true or false");
    return j.get<bool>();
}

std::string getString(const json& j, const std::string& field) {
    if (!j.is_string()) throw Error(field + " must be a string");
    return j.get<std::string>();
}

Vec3 getVec3(const json& j, const std::string& field) {
    if (!j.is_array() || j.size() != 3) throw Error(field + " must be an array of 3 numbers");
    return {getNumber(j[0], field), getNumber(j[1], field), getNumber(j[2], field)};
}

}  // namespace facetlight::json_fields
