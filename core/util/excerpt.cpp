#include "util/excerpt.h"

namespace facetlight {

std::string excerpt(std::string_view text, size_t maxBytes) {
    if (text.size() <= maxBytes) return std::string(text);
    size_t n = maxBytes;
    while (n > 0 && (static_cast<unsigned char>(text[n]) & 0xc0) == 0x80) --n;  // a continuation byte
    return std::string(text.substr(0, n)) + "...";
}

std::string inQuotes(std::string_view text, size_t maxBytes) {
    return "'" + excerpt(text, maxBytes) + "'";
}

}  // namespace facetlight
