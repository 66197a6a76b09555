#include "crowdsim/bench/closest_name.h"

#include <algorithm>
#include <cctype>
#include <cstddef>

namespace crowdsim {
namespace {

char Lower(char c) { return static_cast<char>(std::tolower(static_cast<unsigned char>(c))); }

// Edits from a to b, case ignored, counting swaps of neighbours (optimal string alignment).
std::size_t Edits(const std::string& a, const std::string& b) {
  const std::size_t n = a.size(), m = b.size();
  std::vector<std::vector<std::size_t>> d(n + 1, std::vector<std::size_t>(m + 1));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= n; ++i) {
    for (std::size_t j = 1; j <= m; ++j) {
      const std::size_t cost = Lower(a[i - 1]) == Lower(b[j - 1]) ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && Lower(a[i - 1]) == Lower(b[j - 2]) &&
          Lower(a[i - 2]) == Lower(b[j - 1])) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[n][m];
}

}  // namespace

std::optional<std::string> ClosestName(const std::string& given,
                                       const std::vector<std::string>& valid) {
  if (given.size() < 3) return std::nullopt;
  std::optional<std::string> best;
  std::size_t best_edits = 0;
  bool tie = false;
  for (const std::string& name : valid) {
    const std::size_t longer = std::max(given.size(), name.size());
    const std::size_t limit = std::max<std::size_t>(1, longer / 4);
    const std::size_t edits = Edits(given, name);
    if (name == given || edits > limit) continue;  // the same name is not a suggestion
    if (!best || edits < best_edits) {
      best = name;
      best_edits = edits;
      tie = false;
    } else if (edits == best_edits && name != *best) {
      tie = true;
    }
  }
  if (tie) return std::nullopt;
  return best;
}

std::string DidYouMean(const std::string& given, const std::vector<std::string>& valid) {
  const auto name = ClosestName(given, valid);
  return name ? "; did you mean '" + *name + "'?" : "";
}

}  // namespace crowdsim
