// "Did you mean ...?": the closest names by edit distance, for every message
// that rejects a name (keyword, command, group, component).
#pragma once
#include <string>
#include <vector>

namespace aster {

// Levenshtein distance, case-insensitive.
int editDistance(const std::string& a, const std::string& b);

// Candidates within a distance proportional to the word's length, best first.
std::vector<std::string> closestNames(const std::string& word, const std::vector<std::string>& candidates,
                                      std::size_t maxCount = 3);

// " did you mean X?" or "" when nothing is close.
// quoted: 'X' for values, bare X for names.
std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates, bool quoted = false);

// "A, B, C" (at most maxCount names, then ", ...").
std::string joinNames(const std::vector<std::string>& names, std::size_t maxCount = 20);

}  // namespace aster
