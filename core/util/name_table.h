#pragma once
// The names of an enum's values, written once: what settings JSON, CLI flags, help texts and the API schema
// show for it.
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facetlight {

// A snake_case name as people read it: "lower half" for lower_half.
inline std::string spacedName(std::string name) {
    for (char& c : name)
        if (c == '_') c = ' ';
    return name;
}

template <class E>
struct NamedValue {
    E value;
    std::string_view name;
};

template <class E, size_t N>
struct NameTable {
    std::array<NamedValue<E>, N> entries;

    std::string_view name(E value) const {
        for (const auto& e : entries)
            if (e.value == value) return e.name;
        return entries[0].name;
    }
    std::optional<E> find(std::string_view name) const {
        for (const auto& e : entries)
            if (e.name == name) return e.value;
        return std::nullopt;
    }
    std::vector<std::string_view> names() const {
        std::vector<std::string_view> out;
        for (const auto& e : entries) out.push_back(e.name);
        return out;
    }
};

}  // namespace facetlight
