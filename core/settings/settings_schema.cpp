#include "settings/settings_schema.h"

#include <cmath>
#include <sstream>

#include "util/closest_name.h"
#include "util/error.h"
#include "util/excerpt.h"

namespace facetlight::settings {
namespace {

using nlohmann::json;

std::string numberText(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}

std::string rangeText(const NumberRange& r) {
    const bool hasLo = std::isfinite(r.lo), hasHi = std::isfinite(r.hi);
    std::string text = "a number";
    if (hasLo) text += (r.openLo ? " above " : " from ") + numberText(r.lo);
    if (hasHi && r.openHi) text += (hasLo ? " to below " : " below ") + numberText(r.hi);
    if (hasHi && !r.openHi) text += (hasLo && !r.openLo ? " to " : " up to ") + numberText(r.hi);
    return text;
}

}  // namespace

std::string fieldPath(const std::string& parent, const std::string& key) {
    return parent.empty() ? key : parent + "." + key;
}

uint64_t readCount(const json& j, const std::string& path, uint64_t lo, uint64_t hi) {
    std::optional<uint64_t> v;
    if (j.is_number_unsigned()) {
        v = j.get<uint64_t>();
    } else if (j.is_number_integer()) {  // built in memory from a signed type rather than parsed
        if (j.get<int64_t>() >= 0) v = uint64_t(j.get<int64_t>());
    } else if (j.is_number_float()) {
        // 1e6 is a count; 2^64 and above do not fit, and converting them would be undefined.
        const double d = j.get<double>();
        if (d == std::floor(d) && d >= 0 && d < 0x1p64) v = uint64_t(d);
    }
    if (v && *v >= lo && *v <= hi) return *v;
    throw Error(path,
                path + " must be an integer between " + std::to_string(lo) + " and " + std::to_string(hi));
}

double readNumber(const json& j, const std::string& path, const NumberRange& r) {
    const double v = j.is_number() ? j.get<double>() : NAN;
    const bool aboveLo = r.openLo ? v > r.lo : v >= r.lo;
    const bool belowHi = r.openHi ? v < r.hi : v <= r.hi;
    if (!(aboveLo && belowHi && std::isfinite(v))) throw Error(path, path + " must be " + rangeText(r));
    return v;
}

bool readBool(const json& j, const std::string& path) {
    if (!j.is_boolean()) throw Error(path, path + " must be true or false");
    return j.get<bool>();
}

std::string readText(const json& j, const std::string& path) {
    if (!j.is_string()) throw Error(path, path + " must be a string");
    if (j.get_ref<const std::string&>().size() > kMaxTextBytes)
        throw Error(path, path + " is longer than " + std::to_string(kMaxTextBytes) + " bytes");
    return j.get<std::string>();
}

std::string readChoice(const json& j, const std::string& path, const std::vector<std::string>& choices) {
    const std::string name = readText(j, path);
    std::string known;
    for (const std::string& c : choices) {
        if (c == name) return name;
        known += (known.empty() ? "" : ", ") + c;
    }
    throw Error(path, path + " must be one of " + known + " (got " + inQuotes(name) + ")" +
                          didYouMean(name, choices));
}

Vec3 readVec3(const json& j, const std::string& path, bool nonZero) {
    if (!j.is_array() || j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())
        throw Error(path, path + " must be an array of 3 numbers");
    const Vec3 v{j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
    if (!isFinite(v) || (nonZero && length(v) < 1e-12))
        throw Error(path, path + (nonZero ? " must be a finite, non-zero vector" : " must be finite"));
    return v;
}

void checkObject(const json& j, const std::string& path, const std::vector<FieldInfo>& fields) {
    if (!j.is_object())
        throw Error(path, (path.empty() ? std::string("settings") : path) + " must be a JSON object");
    for (const auto& [key, value] : j.items()) {
        bool known = false;
        for (const FieldInfo& f : fields) known = known || f.key == key;
        if (known) continue;
        std::vector<std::string> keys;
        for (const FieldInfo& f : fields) keys.emplace_back(f.key);
        const std::optional<std::string> meant = closestName(key, keys);
        const std::string name = fieldPath(path, excerpt(key));  // a 100 KB key is no field's name
        throw Error(name, "unknown field '" + name + "'" +
                              (meant ? "; did you mean '" + fieldPath(path, *meant) + "'?" : ""));
    }
}

}  // namespace facetlight::settings
