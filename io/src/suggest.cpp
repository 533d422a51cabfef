#include "suggest.hpp"

#include <algorithm>
#include <cctype>

namespace relpos::detail {
namespace {

char lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// The optimal-string-alignment distance, stopping early once every entry of a row exceeds
// `limit` (names are short; a long unknown key costs one row).
int editDistance(std::string_view a, std::string_view b, int limit) {
  const std::size_t n = a.size(), m = b.size();
  if (static_cast<int>(n > m ? n - m : m - n) > limit) return limit + 1;
  std::vector<int> before(m + 1), prev(m + 1), row(m + 1);
  for (std::size_t j = 0; j <= m; ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= n; ++i) {
    row[0] = static_cast<int>(i);
    int best = row[0];
    for (std::size_t j = 1; j <= m; ++j) {
      const int cost = lower(a[i - 1]) == lower(b[j - 1]) ? 0 : 1;
      row[j] = std::min({prev[j] + 1, row[j - 1] + 1, prev[j - 1] + cost});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        row[j] = std::min(row[j], before[j - 2] + 1);
      best = std::min(best, row[j]);
    }
    if (best > limit) return limit + 1;
    std::swap(before, prev);
    std::swap(prev, row);
  }
  return prev[m];
}

}  // namespace

std::string closestName(std::string_view word, const std::vector<std::string_view>& candidates) {
  const int limit = word.size() <= 4 ? 1 : (word.size() <= 8 ? 2 : 3);
  int best = limit + 1;
  std::string_view found;
  bool tie = false;
  for (std::string_view c : candidates) {
    if (c == word) continue;
    const int d = editDistance(word, c, limit);
    if (d < best) {
      best = d;
      found = c;
      tie = false;
    } else if (d == best && d <= limit) {
      tie = true;
    }
  }
  return best <= limit && !tie ? std::string(found) : std::string();
}

std::string didYouMean(std::string_view word, const std::vector<std::string_view>& candidates) {
  const std::string name = closestName(word, candidates);
  return name.empty() ? std::string() : "; did you mean '" + name + "'?";
}

}  // namespace relpos::detail
