// How the scene reader shows what it read in a message, and the one check of a scene's text that
// toml++ cannot be trusted with (non-ASCII bytes outside comments).
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace impact {

// Messages show at most this much of a value.
constexpr std::size_t kShowLimit = 200;

// A key as typed, with control characters shown as \xNN.
std::string printable(std::string_view key);
// The shortest decimal that reads back as x.
std::string show_number(double x);
// A string value in TOML syntax.
std::string show_string(std::string_view text);
// A value as it would be written in TOML, cut at kShowLimit characters.
std::string show(const toml::node& node, int depth = 0);
// "a, b, c".
std::string join(const std::vector<std::string_view>& names);
// Where the first non-ASCII byte outside a comment is, or npos.
std::size_t find_non_ascii_outside_comments(std::string_view text);

}  // namespace impact
