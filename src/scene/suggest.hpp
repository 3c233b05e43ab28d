// "Did you mean time.h?": the names closest to a mistyped one.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace impact {

// Damerau-Levenshtein distance (optimal string alignment: insertions, deletions, substitutions
// and swaps of two neighbours), ignoring case.
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidates `typed` most likely meant, the nearest only: the same but for case, then one
// containing the other (3 characters or more), then within 2 edits and at most half the longer
// name (so that x does not suggest h). None if nothing is that near.
std::vector<std::string_view> nearest(std::string_view typed,
                                      const std::vector<std::string_view>& candidates);

// "; did you mean <prefix>a?" (or "a or b"), or "" when nothing is near.
std::string did_you_mean(std::string_view typed, const std::vector<std::string_view>& candidates,
                         std::string_view prefix = {});

}  // namespace impact
