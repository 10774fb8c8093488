// "Did you mean RS-44?": the name an operator most likely meant when what was typed names nothing.
// Names are compared without case, blanks and punctuation first ("rs44", "RS 44" and "Rs-44" are
// RS-44), then by edit distance (at most 2 letters wrong, "RS-40" for "RS-44"; at most 1 for names
// of 4 or fewer letters). Pure, header-only.
#pragma once
#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::text {

inline std::string name_key(std::string_view s) {
  std::string k;
  for (const char c : s)
    if (std::isalnum(static_cast<unsigned char>(c))) k.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  return k;
}

// Levenshtein distance, stopping at `limit` + 1.
inline std::size_t edit_distance(std::string_view a, std::string_view b, std::size_t limit) {
  if (a.size() > b.size() + limit || b.size() > a.size() + limit) return limit + 1;
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    std::size_t best = row[0];
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
      best = std::min(best, row[j]);
    }
    if (best > limit) return limit + 1;
  }
  return row[b.size()];
}

// The one name meant, or nothing when none is close or two are equally close.
inline std::optional<std::string> closest_name(std::string_view typed, const std::vector<std::string>& names) {
  const std::string want = name_key(typed);
  if (want.empty()) return std::nullopt;
  for (const std::string& n : names)
    if (name_key(n) == want) return n;
  const std::size_t limit = want.size() <= 4 ? 1 : 2;
  std::optional<std::string> best;
  std::size_t best_d = limit + 1;
  bool tie = false;
  for (const std::string& n : names) {
    const std::size_t d = edit_distance(want, name_key(n), limit);
    if (d < best_d) best = n, best_d = d, tie = false;
    else if (d == best_d && d <= limit && best && *best != n) tie = true;
  }
  if (best_d > limit || tie) return std::nullopt;
  return best;
}

// "; did you mean RS-44?" or "".
inline std::string did_you_mean(std::string_view typed, const std::vector<std::string>& names) {
  const auto n = closest_name(typed, names);
  return n ? "; did you mean " + *n + "?" : std::string();
}

}  // namespace tb::text
