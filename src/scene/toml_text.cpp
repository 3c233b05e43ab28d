// How the scene reader shows what it read in a message: keys, numbers, strings and TOML values,
// made safe for a terminal and cut to a readable length.
#include "scene/toml_text.hpp"

#include <algorithm>
#include <charconv>
#include <cstdio>
#include <sstream>

namespace impact {

// A key as typed, with control characters shown as \xNN, so that a message cannot send escape
// sequences to the terminal.
std::string printable(std::string_view key) {
  std::string out;
  for (unsigned char c : key) {
    if (c < 0x20 || c == 0x7f) {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// Where the first non-ASCII byte outside a comment is, or npos. toml++ 3.3 classifies a non-ASCII
// character wherever whitespace may follow (between tokens, in keys and values, after a
// line-ending backslash) with a lookup that reaches __builtin_unreachable for many code points,
// e.g. U+00A1..U+0499 (toml++ issues #190 and #295): undefined behaviour in the packaged library,
// found by tests/fuzz. A scene's keys and values are ASCII anyway, so a scene may use other
// characters only in comments, where toml++ checks nothing but control characters and surrogates.
// The states follow TOML's strings (basic with escapes, literal, and their multi-line forms).
std::size_t find_non_ascii_outside_comments(std::string_view text) {
  enum class In { code, comment, basic, literal, multiline_basic, multiline_literal };
  In in = In::code;
  const auto non_ascii = [&](std::size_t i) {
    return i < text.size() && static_cast<unsigned char>(text[i]) >= 0x80;
  };
  const auto quotes_at = [&](std::size_t i, char q) {
    std::size_t n = 0;
    while (i + n < text.size() && text[i + n] == q) ++n;
    return n;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (in != In::comment && non_ascii(i)) return i;
    switch (in) {
      case In::code:
        if (c == '#') {
          in = In::comment;
        } else if (c == '"' || c == '\'') {
          const bool triple = quotes_at(i, c) >= 3;
          if (c == '"') in = triple ? In::multiline_basic : In::basic;
          if (c == '\'') in = triple ? In::multiline_literal : In::literal;
          if (triple) i += 2;
        }
        break;
      case In::comment:
        if (c == '\n') in = In::code;
        break;
      case In::basic:
      case In::multiline_basic:
        if (c == '\\') {  // the escaped character is inside the string too
          if (non_ascii(i + 1)) return i + 1;
          ++i;
        } else if (c == '\n' && in == In::basic) {
          in = In::code;  // an unterminated string: toml++ reports it
        } else if (c == '"' && (in == In::basic || quotes_at(i, c) >= 3)) {
          // A multi-line string may end in up to two quotes of its own before the closing three.
          if (in == In::multiline_basic) i += std::min<std::size_t>(quotes_at(i, c), 5) - 1;
          in = In::code;
        }
        break;
      case In::literal:
      case In::multiline_literal:
        if (c == '\n' && in == In::literal) {
          in = In::code;
        } else if (c == '\'' && (in == In::literal || quotes_at(i, c) >= 3)) {
          if (in == In::multiline_literal) i += std::min<std::size_t>(quotes_at(i, c), 5) - 1;
          in = In::code;
        }
        break;
    }
  }
  return std::string_view::npos;
}

// The shortest decimal that reads back as x (1e-15, not toml++'s 1.0000000000000001e-15).
std::string show_number(double x) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

// A string value in TOML syntax: 'literal' when it can be, else "basic" with escapes.
std::string show_string(std::string_view text) {
  bool literal = true;
  for (unsigned char c : text) literal = literal && c >= 0x20 && c != 0x7f && c != '\'';
  if (literal) {
    // Appended piece by piece: GCC 12 reports a false -Wrestrict for "'" + std::string(text).
    std::string out(1, '\'');
    out.append(text);
    out += '\'';
    return out;
  }
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c == 0x7f) {
      char escape[8];
      std::snprintf(escape, sizeof escape, "\\u%04x", c);
      out += escape;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

// A value as it would be written in TOML, for messages. Written here, not by toml++: its formatter
// lays out arrays by converting log10 of each number to size_t, which is undefined for nan, inf,
// |x| < 0.1 and INT64_MIN (found by tests/fuzz), and classifies non-ASCII characters of strings
// with the lookup of find_non_ascii_outside_comments().
std::string show(const toml::node& node, int depth) {
  std::string out;
  if (const auto* x = node.as_floating_point()) {
    out = show_number(x->get());
  } else if (const auto* i = node.as_integer()) {
    out = std::to_string(i->get());
  } else if (const auto* b = node.as_boolean()) {
    out = b->get() ? "true" : "false";
  } else if (const auto* str = node.as_string()) {
    out = show_string(str->get());
  } else if (const auto* array = node.as_array()) {
    out = "[";
    for (const toml::node& item : *array) {
      if (out.size() > kShowLimit) break;
      out += (out.size() > 1 ? ", " : "") + (depth < 8 ? show(item, depth + 1) : "...");
    }
    out += "]";
  } else if (const auto* table = node.as_table()) {
    out = "{";
    for (auto&& [key, value] : *table) {
      if (out.size() > kShowLimit) break;
      out += (out.size() > 1 ? ", " : "") + printable(key.str()) + " = " +
             (depth < 8 ? show(value, depth + 1) : "...");
    }
    out += "}";
  } else {  // a date, time or date-time: digits and separators only
    std::ostringstream text;
    node.visit([&](auto&& v) { text << v; });
    out = text.str();
  }
  if (out.size() > kShowLimit) out = out.substr(0, kShowLimit) + "...";
  return out;
}

std::string join(const std::vector<std::string_view>& names) {
  std::string out;
  for (auto name : names) out += (out.empty() ? "" : ", ") + std::string(name);
  return out;
}

}  // namespace impact
