#pragma once
// CLI flags made from a settings table (core/settings/settings_schema.h): one flag per field, with the
// table's help, unit and the defaults shown. The flags given are read through the same schema as JSON, so the
// CLI checks exactly what the service checks; errors name the flag. Header-only: the CLI's build takes its
// sources from cli/*_command.cpp.
#include <algorithm>
#include <charconv>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "settings/settings_schema.h"
#include "util/error.h"

namespace facetlight::cli {

class SettingsFlags {
  public:
    // Adds the flags of `fields` (and of the objects among them) to `cmd`. `path` is the settings' own
    // dotted path ("render" for the render settings); `defaults` their JSON, shown in the help.
    void add(CLI::App* cmd, const std::vector<settings::FieldInfo>& fields, const nlohmann::json& defaults,
             const std::string& path = "") {
        root_ = path;
        addFields(cmd, fields, defaults, "");
    }

    // Whether any of the flags was given.
    bool given() const {
        for (const Flag& f : flags_)
            if (f.option->count() > 0) return true;
        return false;
    }

    // Reads the flags given onto `s`. Throws Error naming the flag.
    template <class S>
    void apply(const settings::Schema<S>& schema, S& s) const {
        nlohmann::json given = nlohmann::json::object();
        for (const Flag& f : flags_)
            if (f.option->count() > 0) given[nlohmann::json::json_pointer(f.pointer)] = value(f);
        try {
            schema.read(s, given, root_);
        } catch (const Error& e) {
            for (const Flag& f : flags_) {
                const std::string path = settings::fieldPath(root_, f.path);
                if (path == e.field()) throw Error(f.field->doc.flag, message(f, e.what()));
                if (e.field().rfind(path + ".", 0) == 0)  // inside a table the flag gave
                    throw Error(f.field->doc.flag, f.field->doc.flag + ": " + e.what());
            }
            throw;
        }
    }

  private:
    struct Flag {
        std::string path;     // below the settings' own path
        std::string pointer;  // the same as a JSON pointer
        const settings::FieldInfo* field;
        CLI::Option* option;
    };

    static std::string text(const nlohmann::json& v) {
        if (v.is_string()) return v.get<std::string>();
        if (v.is_number_float()) {
            std::ostringstream s;
            s << v.get<double>();
            return s.str();
        }
        if (v.is_array()) {
            std::string words;
            for (const auto& x : v) words += (words.empty() ? "" : " ") + text(x);
            return words;
        }
        return v.is_null() ? "" : v.dump();
    }

    static std::string help(const settings::FieldInfo& f) {
        std::string h = f.doc.help;
        for (size_t i = 0; i < f.choices.size(); ++i)
            h += (i == 0 ? ": " : i + 1 == f.choices.size() ? " or " : ", ") + f.choices[i];
        if (!f.doc.unit.empty()) h += ", " + f.doc.unit;
        return h;
    }

    void addFields(CLI::App* cmd, const std::vector<settings::FieldInfo>& fields,
                   const nlohmann::json& defaults, const std::string& path) {
        for (const settings::FieldInfo& f : fields) {
            const std::string at = settings::fieldPath(path, f.key);
            if (f.type == settings::FieldType::Object) {
                addFields(cmd, *f.fields, defaults.at(f.key), at);
                continue;
            }
            std::string pointer = "/" + at;
            for (char& c : pointer) c = c == '.' ? '/' : c;
            CLI::Option* option = nullptr;
            const std::string names =
                f.doc.formerFlag.empty() ? f.doc.flag : f.doc.flag + "," + f.doc.formerFlag;
            if (f.type == settings::FieldType::Boolean) {
                option = cmd->add_flag(names)->description(help(f));
            } else {
                option = cmd->add_option(names)->description(help(f));
                if (f.type == settings::FieldType::Vec3) option->expected(3);
                if (const std::string d = text(defaults.at(f.key)); !d.empty()) option->default_str(d);
            }
            flags_.push_back({at, pointer, &f, option});
        }
    }

    // The flag's words as JSON of the field's type; words that are not one stay strings, which the schema
    // refuses with the field's own message.
    static nlohmann::json value(const Flag& f) {
        const std::vector<std::string>& words = f.option->results();
        const auto number = [](const std::string& w) -> nlohmann::json {
            uint64_t whole = 0;
            if (auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), whole);
                ec == std::errc() && end == w.data() + w.size())
                return whole;  // exact, however large
            size_t used = 0;
            try {
                const double v = std::stod(w, &used);
                if (used == w.size()) return v;
            } catch (const std::exception&) {
            }
            return w;
        };
        switch (f.field->type) {
            case settings::FieldType::Boolean:
                return f.field->doc.flag.rfind("--no-", 0) != 0;
            case settings::FieldType::Integer:
            case settings::FieldType::Number:
                return number(words.at(0));
            case settings::FieldType::Vec3: {
                nlohmann::json v = nlohmann::json::array();
                for (const std::string& w : words) v.push_back(number(w));
                return v;
            }
            case settings::FieldType::Table:
                return table(f, words.at(0));
            default:
                return words.at(0);
        }
    }

    // A table flag's JSON: written inline ("{...}") or the path of a file holding it.
    static nlohmann::json table(const Flag& f, const std::string& word) {
        const std::string& flag = f.field->doc.flag;
        const size_t first = word.find_first_not_of(" \t\r\n");
        std::string text = word;
        if (first == std::string::npos || word[first] != '{') {
            std::ifstream in(word);
            if (!in)
                throw Error(flag, flag + ": cannot read '" + word + "' (give the JSON inline or a file)");
            text.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
        try {
            return nlohmann::json::parse(text);
        } catch (const nlohmann::json::parse_error& e) {
            throw Error(flag, flag + ": not JSON (" + e.what() + ")");
        }
    }

    // "render.width must be ..." becomes "--width must be ... (got '8')".
    std::string message(const Flag& f, const std::string& what) const {
        const std::string field = settings::fieldPath(root_, f.path) + " ";
        std::string words;
        for (const std::string& w : f.option->results()) words += (words.empty() ? "" : " ") + w;
        const bool quoted =
            f.field->type == settings::FieldType::Boolean || what.find("(got '") != std::string::npos;
        const std::string got = quoted ? "" : " (got '" + words + "')";
        if (what.rfind(field, 0) == 0) return f.field->doc.flag + " " + what.substr(field.size()) + got;
        return f.field->doc.flag + ": " + what;
    }

    std::string root_;
    std::vector<Flag> flags_;
};

// A view's switch (--aset, --colour, ...) and its own flags, any of which turns the view on with the defaults
// for the flags not given.
template <class S>
class ViewFlags {
  public:
    // `name` is the switch ("--colour"), `path` the view's settings path ("colour").
    void add(CLI::App* cmd, const std::string& name, const std::string& help,
             const settings::Schema<S>& schema, const std::string& path) {
        schema_ = &schema;
        cmd->add_flag(name, on_, help + "; any " + name + "-... flag implies it");
        flags_.add(cmd, schema.fields(), schema.write(S{}), path);
    }

    // The view's settings, or none when neither the switch nor any of its flags was given. Throws Error
    // naming the flag.
    std::optional<S> read() const {
        if (!on_ && !flags_.given()) return std::nullopt;
        S s;
        flags_.apply(*schema_, s);
        return s;
    }

  private:
    bool on_ = false;
    SettingsFlags flags_;
    const settings::Schema<S>* schema_ = nullptr;
};

}  // namespace facetlight::cli
