#pragma once
// Suggestions for misspelt names (unknown keys, methods, integrators).

#include <string>
#include <vector>

namespace sl {

// Levenshtein distance, case-sensitive.
int editDistance(const std::string& a, const std::string& b);

// The closest candidate within a distance that still looks like a typo (a third of the word, at
// least 1, at most 3), or "" when none is close.
std::string closestName(const std::string& word, const std::vector<std::string>& candidates);

// " (did you mean \"x\"?)" or "".
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace sl
