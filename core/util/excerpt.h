#pragma once
// Input quoted in a message: at most a short excerpt of it, so that a 100 KB name or number sent to the
// service does not come back whole in its error (issue 31).
#include <cstddef>
#include <string>
#include <string_view>

namespace facetlight {

constexpr size_t kExcerptBytes = 40;

// `text` cut after `maxBytes` (never inside a UTF-8 character), with "..." where it was cut.
std::string excerpt(std::string_view text, size_t maxBytes = kExcerptBytes);
// The excerpt in single quotes.
std::string inQuotes(std::string_view text, size_t maxBytes = kExcerptBytes);

}  // namespace facetlight
