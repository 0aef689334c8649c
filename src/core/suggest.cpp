#include "core/suggest.hpp"

#include <algorithm>
#include <cctype>

namespace aster {

namespace {
int distance(const std::string& a, const std::string& b, bool ignoreCase) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = ignoreCase ? std::toupper(static_cast<unsigned char>(a[i - 1])) ==
                                         std::toupper(static_cast<unsigned char>(b[j - 1]))
                                   : a[i - 1] == b[j - 1];
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}
}  // namespace

int editDistance(const std::string& a, const std::string& b) { return distance(a, b, true); }

std::vector<std::string> closestNames(const std::string& word, const std::vector<std::string>& candidates,
                                      std::size_t maxCount) {
  // Allow about one edit per three letters, at least two.
  const int limit = std::max<int>(2, static_cast<int>(word.size()) / 3);
  // Ties go to the candidate that also matches the letter case (DEBUT before debug).
  std::vector<std::pair<std::pair<int, int>, std::string>> scored;
  for (const auto& c : candidates) {
    const int d = editDistance(word, c);
    if (d <= limit) scored.push_back({{d, distance(word, c, false)}, c});
  }
  std::sort(scored.begin(), scored.end());
  std::vector<std::string> out;
  for (const auto& s : scored) {
    if (out.size() >= maxCount) break;
    if (std::find(out.begin(), out.end(), s.second) == out.end()) out.push_back(s.second);
  }
  return out;
}

std::string didYouMean(const std::string& word, const std::vector<std::string>& candidates, bool quoted) {
  const auto best = closestNames(word, candidates, 3);
  if (best.empty()) return "";
  std::string s = " did you mean ";
  for (std::size_t i = 0; i < best.size(); ++i) {
    if (i) s += (i + 1 == best.size()) ? " or " : ", ";
    s += quoted ? "'" + best[i] + "'" : best[i];
  }
  return s + "?";
}

std::string joinNames(const std::vector<std::string>& names, std::size_t maxCount) {
  std::string s;
  for (std::size_t i = 0; i < names.size() && i < maxCount; ++i) {
    if (i) s += ", ";
    s += names[i];
  }
  if (names.size() > maxCount) s += ", ...";
  return s;
}

}  // namespace aster
