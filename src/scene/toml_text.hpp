// How the scene reader shows what it read in a message, and the checks of a scene's text that
// toml++ cannot be trusted with (non-ASCII bytes outside comments, deep nesting).
#pragma once

#include <toml++/toml.h>

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace impact {

// Messages show at most this much of a value.
constexpr std::size_t kShowLimit = 200;

// A key as typed, with control characters shown as \xNN.
std::string printable(std::string_view key);
// Text as typed, made printable and cut at kShowLimit characters.
std::string cut(std::string_view text);
// A float as TOML writes it (1.0, 1e-15, nan).
std::string show_float(double x);
// A string value in TOML syntax.
std::string show_string(std::string_view text);
// A key as TOML needs it written: bare, or quoted when it is not a bare key; cut at kShowLimit.
std::string show_key(std::string_view key);
// A value as it would be written in TOML, cut at kShowLimit characters.
std::string show(const toml::node& node, int depth = 0);
// "a, b, c".
std::string join(const std::vector<std::string_view>& names);
// Where a byte of a TOML text is.
enum class TomlPart { code, comment, string };
// The first byte i of `text` for which stop(i, part) is true, or npos.
std::size_t find_in_toml(std::string_view text,
                         const std::function<bool(std::size_t, TomlPart)>& stop);

// Where the first non-ASCII byte outside a comment is, or npos.
std::size_t find_non_ascii_outside_comments(std::string_view text);

// A scene's keys have at most this many dotted parts, and its values nest at most this deep.
constexpr std::size_t kMaxKeyParts = 8;
constexpr std::size_t kMaxNesting = 8;
struct TooDeep {
  std::size_t at = std::string_view::npos;  // the '.', '[' or '{' past the bound, or npos
  bool key = false;                         // a dotted key, else nested values
  std::string what() const;
};
// The first key or value nested beyond those bounds.
TooDeep find_too_deep(std::string_view text);

// "line:column" of byte `at` of `text`, as toml++ counts them.
std::string line_and_column(std::string_view text, std::size_t at);

}  // namespace impact
