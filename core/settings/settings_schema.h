#pragma once
// One description per setting (after Tungsten: settings apart from the algorithm, each described once): a
// settings struct has a table of fields (JSON key, member, type, range, unit, CLI flag, help). Reading and
// writing JSON, the checks, the CLI's flags (cli/settings_flags.h) and the API schema (tested against
// server/openapi.json) all follow from the table. Reading is strict, since the server feeds it untrusted
// JSON: an unknown key, a wrong type or a value out of range throws Error with the field's dotted path.
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "geometry/geometry.h"
#include "util/name_table.h"

namespace facetlight::settings {

// Table: a value of its own JSON form (a spectrum), read and written by the row's own functions.
enum class FieldType { Integer, Number, Boolean, Text, Choice, Vec3, Object, Table };

// How a number may range; open ends exclude their bound.
struct NumberRange {
    double lo = -std::numeric_limits<double>::infinity();
    double hi = std::numeric_limits<double>::infinity();
    bool openLo = false;
    bool openHi = false;
};

// What a table row says about its field, apart from the struct holding it.
struct Doc {
    Doc() = default;
    Doc(std::string flag, std::string help, std::string unit = "", std::string formerFlag = "")
        : flag(std::move(flag)),
          help(std::move(help)),
          unit(std::move(unit)),
          formerFlag(std::move(formerFlag)) {}

    std::string flag;        // the CLI flag, e.g. "--max-bounces"; a Boolean's "--no-..." flag sets it false
    std::string help;        // CLI help
    std::string unit;        // e.g. "degrees"; empty: none
    std::string formerFlag;  // an earlier name the CLI still accepts, so that old command lines keep working
};

struct FieldInfo {
    std::string key;  // the JSON key
    FieldType type = FieldType::Integer;
    Doc doc;
    uint64_t minCount = 0, maxCount = 0;             // Integer: whole numbers in [minCount, maxCount]
    NumberRange range;                               // Number
    bool nullable = false;                           // Number, Table: null means none
    bool nonZero = false;                            // Vec3: not the zero vector
    std::vector<std::string> choices;                // Choice: the names it takes
    const std::vector<FieldInfo>* fields = nullptr;  // Object: its own table
    std::string ref;                                 // Table: its schema's name in server/openapi.json
};

// A row's description; the builders below fill in the rest.
inline FieldInfo describe(std::string key, FieldType type, Doc doc = {}) {
    FieldInfo info;
    info.key = std::move(key);
    info.type = type;
    info.doc = std::move(doc);
    return info;
}

// "render" + "width" -> "render.width"; "" + "photons" -> "photons".
std::string fieldPath(const std::string& parent, const std::string& key);

// The strict readers of one JSON value, throwing Error(path, "<path> must be ...").
uint64_t readCount(const nlohmann::json& j, const std::string& path, uint64_t lo, uint64_t hi);
double readNumber(const nlohmann::json& j, const std::string& path, const NumberRange& range);
bool readBool(const nlohmann::json& j, const std::string& path);
// Free text (a job's name, a mesh, a constraint, a choice) is at most this long: 40 jobs named with 900 000
// characters each made one page of the job list 36 MB (issue 31).
constexpr size_t kMaxTextBytes = 1024;
std::string readText(const nlohmann::json& j, const std::string& path);
std::string readChoice(const nlohmann::json& j, const std::string& path,
                       const std::vector<std::string>& choices);
Vec3 readVec3(const nlohmann::json& j, const std::string& path, bool nonZero);
// Refuses a non-object and any key not in `fields`.
void checkObject(const nlohmann::json& j, const std::string& path, const std::vector<FieldInfo>& fields);

template <class S>
struct Field {
    FieldInfo info;
    std::function<void(S&, const nlohmann::json&, const std::string& path)> read;
    std::function<nlohmann::json(const S&)> write;
};

template <class S>
class Schema {
  public:
    // `check`: what concerns several fields together, after they are read.
    explicit Schema(std::vector<Field<S>> fields,
                    std::function<void(const S&, const std::string&)> check = {})
        : fields_(std::move(fields)), check_(std::move(check)) {
        for (const Field<S>& f : fields_) infos_.push_back(f.info);
    }

    // Reads the keys `j` has into `s` (the others keep their values) and checks the result. `path` is j's
    // own dotted path ("" at the top), for the errors.
    void read(S& s, const nlohmann::json& j, const std::string& path = "") const {
        checkObject(j, path, infos_);
        for (const Field<S>& f : fields_)
            if (const auto it = j.find(f.info.key); it != j.end())
                f.read(s, *it, fieldPath(path, f.info.key));
        if (check_) check_(s, path);
    }
    S read(const nlohmann::json& j, const std::string& path = "") const {
        S s;
        read(s, j, path);
        return s;
    }
    // Every field written out.
    nlohmann::json write(const S& s) const {
        nlohmann::json j = nlohmann::json::object();
        for (const Field<S>& f : fields_) j[f.info.key] = f.write(s);
        return j;
    }
    const std::vector<FieldInfo>& fields() const { return infos_; }

  private:
    std::vector<Field<S>> fields_;
    std::vector<FieldInfo> infos_;
    std::function<void(const S&, const std::string&)> check_;
};

// The table rows, one per kind of field.

// A member of S's base class B as a member of S, for a row of S's table: `inherited<S>(&S::field)`.
template <class S, class B, class T>
constexpr T S::*inherited(T B::*member) {
    return member;
}

template <class S, class T>
Field<S> count(std::string key, T S::*member, uint64_t lo, uint64_t hi, Doc doc) {
    static_assert(std::is_integral_v<T>);
    FieldInfo info = describe(std::move(key), FieldType::Integer, std::move(doc));
    info.minCount = lo;
    info.maxCount = hi;
    return {std::move(info),
            [=](S& s, const nlohmann::json& j, const std::string& path) {
                s.*member = T(readCount(j, path, lo, hi));
            },
            [=](const S& s) { return nlohmann::json(s.*member); }};
}

template <class S>
Field<S> number(std::string key, double S::*member, NumberRange range, Doc doc) {
    FieldInfo info = describe(std::move(key), FieldType::Number, std::move(doc));
    info.range = range;
    return {std::move(info),
            [=](S& s, const nlohmann::json& j, const std::string& path) {
                s.*member = readNumber(j, path, range);
            },
            [=](const S& s) { return nlohmann::json(s.*member); }};
}

// Absent or null: none.
template <class S>
Field<S> optionalNumber(std::string key, std::optional<double> S::*member, NumberRange range, Doc doc) {
    FieldInfo info = describe(std::move(key), FieldType::Number, std::move(doc));
    info.range = range;
    info.nullable = true;
    return {std::move(info),
            [=](S& s, const nlohmann::json& j, const std::string& path) {
                s.*member = j.is_null() ? std::nullopt : std::optional(readNumber(j, path, range));
            },
            [=](const S& s) { return s.*member ? nlohmann::json(*(s.*member)) : nlohmann::json(nullptr); }};
}

template <class S>
Field<S> boolean(std::string key, bool S::*member, Doc doc) {
    return {describe(std::move(key), FieldType::Boolean, std::move(doc)),
            [=](S& s, const nlohmann::json& j, const std::string& path) { s.*member = readBool(j, path); },
            [=](const S& s) { return nlohmann::json(s.*member); }};
}

template <class S>
Field<S> text(std::string key, std::string S::*member, Doc doc) {
    return {describe(std::move(key), FieldType::Text, std::move(doc)),
            [=](S& s, const nlohmann::json& j, const std::string& path) { s.*member = readText(j, path); },
            [=](const S& s) { return nlohmann::json(s.*member); }};
}

template <class S, class E, size_t N>
Field<S> choice(std::string key, E S::*member, const NameTable<E, N>& names, Doc doc) {
    FieldInfo info = describe(std::move(key), FieldType::Choice, std::move(doc));
    for (std::string_view name : names.names()) info.choices.emplace_back(name);
    return {info,
            [=, choices = info.choices](S& s, const nlohmann::json& j, const std::string& path) {
                s.*member = *names.find(readChoice(j, path, choices));
            },
            [=](const S& s) { return nlohmann::json(names.name(s.*member)); }};
}

template <class S>
Field<S> vec3(std::string key, Vec3 S::*member, bool nonZero, Doc doc) {
    FieldInfo info = describe(std::move(key), FieldType::Vec3, std::move(doc));
    info.nonZero = nonZero;
    return {std::move(info),
            [=](S& s, const nlohmann::json& j, const std::string& path) {
                s.*member = readVec3(j, path, nonZero);
            },
            [=](const S& s) {
                const Vec3& v = s.*member;
                return nlohmann::json::array({v.x, v.y, v.z});
            }};
}

// A table of its own JSON form, `ref` in server/openapi.json's schemas, read by read(json, path) (which
// throws Error naming the field at fault) and written by write(value); absent or null: none.
template <class S, class T>
Field<S> table(std::string key, std::optional<T> S::*member, std::string ref,
               T (*read)(const nlohmann::json&, const std::string&), nlohmann::json (*write)(const T&),
               Doc doc) {
    FieldInfo info = describe(std::move(key), FieldType::Table, std::move(doc));
    info.ref = std::move(ref);
    info.nullable = true;
    return {std::move(info),
            [=](S& s, const nlohmann::json& j, const std::string& path) {
                s.*member = j.is_null() ? std::nullopt : std::optional<T>(read(j, path));
            },
            [=](const S& s) { return s.*member ? write(*(s.*member)) : nlohmann::json(nullptr); }};
}

// A settings struct inside another; `schema` must outlive the table (a function-local static).
template <class S, class T>
Field<S> object(std::string key, T S::*member, const Schema<T>& schema) {
    FieldInfo info = describe(std::move(key), FieldType::Object);
    info.fields = &schema.fields();
    return {std::move(info),
            [member, &schema](S& s, const nlohmann::json& j, const std::string& path) {
                schema.read(s.*member, j, path);
            },
            [member, &schema](const S& s) { return schema.write(s.*member); }};
}

}  // namespace facetlight::settings
