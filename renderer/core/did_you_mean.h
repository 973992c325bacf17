#pragma once
// Spelling suggestions for error messages about unknown names (colour spaces, views, fields...).
#include <string>
#include <vector>

namespace isotrace {

// Returns ` (did you mean "candidate"?)` for the candidate closest to `word` (case-insensitive
// Damerau-Levenshtein distance, small relative to the word's length), or "" when none is close.
std::string did_you_mean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace isotrace
