#include "scene/suggest.hpp"

#include <algorithm>
#include <cctype>

namespace impact {
namespace {

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

bool contains(std::string_view text, std::string_view part) {
  return std::search(text.begin(), text.end(), part.begin(), part.end(),
                     [](char a, char b) { return lower(a) == lower(b); }) != text.end();
}

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // Three rows of the usual table: a swap looks two rows back.
  std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const bool same = lower(a[i - 1]) == lower(b[j - 1]);
      row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + (same ? 0 : 1)});
      if (i > 1 && j > 1 && lower(a[i - 1]) == lower(b[j - 2]) &&
          lower(a[i - 2]) == lower(b[j - 1]))
        row[j] = std::min(row[j], before[j - 2] + 1);
    }
    std::swap(before, previous);
    std::swap(previous, row);
  }
  return previous[b.size()];
}

std::vector<std::string_view> nearest(std::string_view typed,
                                      const std::vector<std::string_view>& candidates) {
  // Scores, best first: the same but for case (COR, cor); one contains the other (newton,
  // fb_newton; rk8, rk8pd); 1 or 2 edits, at most half the longer name (hh, h; not phi, h).
  constexpr std::size_t kMaxEdits = 2, kNone = kMaxEdits + 2;
  std::size_t best = kNone;
  std::vector<std::string_view> found;
  for (std::string_view c : candidates) {
    const std::size_t shorter = std::min(typed.size(), c.size());
    const std::size_t longer = std::max(typed.size(), c.size());
    std::size_t score = kNone;
    // The distance is at least the difference in length: a long input costs nothing here.
    if (longer - shorter <= kMaxEdits) {
      const std::size_t d = edit_distance(typed, c);
      if (d == 0)
        score = 0;
      else if (d <= kMaxEdits && d <= longer / 2)
        score = 1 + d;
    }
    if (score > 1 && shorter >= 3 && (contains(c, typed) || contains(typed, c))) score = 1;
    if (score < best) {
      best = score;
      found.clear();
    }
    if (score == best && score < kNone) found.push_back(c);
  }
  return found;
}

std::string did_you_mean(std::string_view typed, const std::vector<std::string_view>& candidates,
                         std::string_view prefix) {
  const auto names = nearest(typed, candidates);
  if (names.empty()) return "";
  std::string out = "; did you mean ";
  for (std::size_t i = 0; i < names.size(); ++i)
    out.append(i == 0 ? "" : " or ").append(prefix).append(names[i]);
  return out + "?";
}

}  // namespace impact
