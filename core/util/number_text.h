#pragma once
// Numbers in text. Strict number reading for the text loaders: the whole token must be a number (std::from_chars, which,
// unlike strtod, ignores the locale), so "1,5" or "12abc" are refused instead of being half read.
#include <charconv>
#include <cstdio>
#include <string>
#include <string_view>
#include <system_error>

namespace facetlight {

inline bool parseNumber(std::string_view token, double& value) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

inline bool parseInteger(std::string_view token, long long& value) {
    if (token.size() > 1 && token[0] == '+' && token[1] != '-' && token[1] != '+') token.remove_prefix(1);
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
    return ec == std::errc() && end == token.data() + token.size();
}

// One number written with a printf format ("%g", "%.1f"), for labels.
inline std::string formatNumber(const char* format, double v) {
    char text[48];
    std::snprintf(text, sizeof text, format, v);
    return text;
}

}  // namespace facetlight
