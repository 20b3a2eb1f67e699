#pragma once
// Numbers in text. Strict number reading for the text loaders: the whole token must be a number (std::from_chars, which,
// unlike strtod, ignores the locale), so "1,5" or "12abc" are refused instead of being half read.
#include <algorithm>
#include <charconv>
#include <cmath>
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

// The decimals that show an error of `error` to one significant digit, two when it starts with 1 ("0.14",
// "0.3", "2"); at most `most`.
inline int errorDecimals(double error, int most = 6) {
    if (!(error > 0)) return 1;
    int decimals = -int(std::floor(std::log10(error)));
    if (error * std::pow(10.0, decimals) < 2) ++decimals;
    return std::clamp(decimals, 0, most);
}

// "3.1 +- 0.2": a value and its standard error, both to the error's decimals.
inline std::string formatWithError(double value, double error, const char* separator = " +- ") {
    const int d = errorDecimals(error);
    char text[96];
    std::snprintf(text, sizeof text, "%.*f%s%.*f", d, value, separator, d, error);
    return text;
}

}  // namespace facetlight
