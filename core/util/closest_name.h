#pragma once
// "Did you mean ...?" for a mistyped name: the known name nearest to it by edit distance, when it is near
// enough to be the one meant.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace facetlight {

// The candidate at the fewest insertions, deletions, substitutions and swaps of neighbours from `word`
// (case ignored), when that is at most a third of the word's length (at least 1); the first of equals.
std::optional<std::string> closestName(std::string_view word, const std::vector<std::string>& candidates);
// "; did you mean 'NAME'?" for the closest candidate, or "" when none is close.
std::string didYouMean(std::string_view word, const std::vector<std::string>& candidates);

}  // namespace facetlight
