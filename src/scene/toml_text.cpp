// How the scene reader shows what it read in a message: keys, numbers, strings and TOML values,
// made safe for a terminal and cut to a readable length.
#include "scene/toml_text.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdio>
#include <sstream>

#include "impact/format.hpp"

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

// Text as typed (a --set, a parser's description of it), shown with printable() and cut at
// kShowLimit characters, so that a message stays one readable line whatever was typed. The cut
// does not split a UTF-8 sequence.
std::string cut(std::string_view text) {
  std::string out = printable(text);
  if (out.size() <= kShowLimit) return out;
  std::size_t end = kShowLimit;
  while (end > 0 && (static_cast<unsigned char>(out[end]) & 0xC0) == 0x80) --end;
  return out.substr(0, end) + "...";
}

// The lexical states of a TOML text: code, comments, and TOML's strings (basic with escapes,
// literal, and their multi-line forms). Calls stop(i, part) for each byte in order and returns the
// first i for which it is true, or npos. The second and third quote that open or close a
// multi-line string are skipped (they are quotes, and ASCII).
std::size_t find_in_toml(std::string_view text,
                         const std::function<bool(std::size_t, TomlPart)>& stop) {
  enum class In { code, comment, basic, literal, multiline_basic, multiline_literal };
  In in = In::code;
  const auto quotes_at = [&](std::size_t i, char q) {
    std::size_t n = 0;
    while (i + n < text.size() && text[i + n] == q) ++n;
    return n;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (stop(i, in == In::code      ? TomlPart::code
                : in == In::comment ? TomlPart::comment
                                    : TomlPart::string))
      return i;
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
          if (i + 1 < text.size() && stop(i + 1, TomlPart::string)) return i + 1;
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

// toml++ 3.3 classifies a non-ASCII character wherever whitespace may follow (between tokens, in
// keys and values, after a line-ending backslash) with a lookup that reaches
// __builtin_unreachable for many code points, e.g. U+00A1..U+0499 (toml++ issues #190 and #295):
// undefined behaviour in the packaged library, found by tests/fuzz. A scene's keys and values are
// ASCII anyway, so a scene may use other characters only in comments, where toml++ checks nothing
// but control characters and surrogates.
std::size_t find_non_ascii_outside_comments(std::string_view text) {
  return find_in_toml(text, [&](std::size_t i, TomlPart part) {
    return part != TomlPart::comment && static_cast<unsigned char>(text[i]) >= 0x80;
  });
}

// toml++ 3.3 makes a table of each part of a dotted key or table name and later walks and frees
// them recursively, one stack frame per part: 40000 parts overflow 8 MiB of stack, 6000 parts
// 1 MiB. It stops nested arrays and inline tables at 256, but 256 inline tables with a dotted key
// in each are thousands of tables again. A scene's keys have two parts (table.key) and its values
// nest one level (output.channels), so far lower bounds cost nothing and make the parse independent
// of the stack size. Dots count only where a key can be: not in strings or comments, and not in
// values (1.5), except in the keys of an inline table.
TooDeep find_too_deep(std::string_view text) {
  std::vector<char> open;  // the arrays '[' and inline tables '{' around the current byte
  bool value = false;      // after '=' or inside an array: not a key
  std::size_t dots = 0;    // in the dotted key being read
  TooDeep found;
  found.at = find_in_toml(text, [&](std::size_t i, TomlPart part) {
    if (part != TomlPart::code) return false;
    const char c = text[i];
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == ' ' ||
        c == '\t' || c == '"' || c == '\'')
      return false;  // inside a key (a quoted part is a string, skipped)
    if (c == '.') {
      found.key = true;
      return !value && ++dots >= kMaxKeyParts;
    }
    dots = 0;
    if (c == '=') {
      value = true;
    } else if (c == '\n') {
      value = value && !open.empty();  // a multi-line array goes on
    } else if (c == '[' && (value || !open.empty())) {
      open.push_back('[');  // an array, not a table header
      value = true;
    } else if (c == '{') {
      open.push_back('{');
      value = false;  // its keys come first
    } else if ((c == ']' || c == '}') && !open.empty() && open.back() == (c == ']' ? '[' : '{')) {
      open.pop_back();
      value = true;  // what closed was a value
    } else if (c == ',' && !open.empty()) {
      value = open.back() == '[';  // the next element, or the next key of an inline table
    }
    found.key = false;
    return open.size() > kMaxNesting;
  });
  return found;
}

std::string TooDeep::what() const {
  return key ? "a dotted key or table name of more than " + std::to_string(kMaxKeyParts) +
                   " parts (a scene's keys are table.key)"
             : "arrays and inline tables nested more than " + std::to_string(kMaxNesting) +
                   " deep (a scene's values are numbers, names and one list of names)";
}

// "line:column" of byte `at`, as toml++ counts them: the column in characters, not bytes.
std::string line_and_column(std::string_view text, std::size_t at) {
  const std::size_t newline = text.rfind('\n', at);
  const std::size_t line_start = newline == std::string_view::npos ? 0 : newline + 1;
  const std::size_t line =
      1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + at, '\n'));
  std::size_t column = 1;
  for (std::size_t i = line_start; i < at; ++i)
    column += (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;  // not a continuation byte
  return std::to_string(line) + ":" + std::to_string(column);
}

// A TOML basic string: "..." with quotes, backslashes and control characters escaped.
std::string basic_string(std::string_view text) {
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

// A string value in TOML syntax: 'literal' when it can be, else "basic" with escapes.
std::string show_string(std::string_view text) {
  bool literal = true;
  for (unsigned char c : text) literal = literal && c >= 0x20 && c != 0x7f && c != '\'';
  if (!literal) return basic_string(text);
  // Appended piece by piece: GCC 12 reports a false -Wrestrict for "'" + std::string(text).
  std::string out(1, '\'');
  out.append(text);
  out += '\'';
  return out;
}

// A key as TOML would need it written: bare when it is a bare key (letters, digits, _ and -),
// else quoted, so that `"u0 " = 5` shows as initial."u0 " and the space is seen. Cut at
// kShowLimit characters.
std::string show_key(std::string_view key) {
  const bool bare = !key.empty() && std::all_of(key.begin(), key.end(), [](unsigned char c) {
    return std::isalnum(c) || c == '_' || c == '-';
  });
  std::string out = bare ? std::string(key) : basic_string(key);
  if (out.size() > kShowLimit) out = out.substr(0, kShowLimit) + "...";
  return out;
}

// A float as TOML writes it: a whole number keeps its ".0" (1.0, not 1), so that a message about
// a key that needs an integer shows why the value is not one.
std::string show_float(double x) {
  std::string out = shortest(x);
  if (out.find_first_of(".en") == std::string::npos) out += ".0";  // not 1e+20, nan, inf
  return out;
}

// A value as it would be written in TOML, for messages. Written here, not by toml++: its formatter
// lays out arrays by converting log10 of each number to size_t, which is undefined for nan, inf,
// |x| < 0.1 and INT64_MIN (found by tests/fuzz), and classifies non-ASCII characters of strings
// with the lookup of find_non_ascii_outside_comments().
std::string show(const toml::node& node, int depth) {
  std::string out;
  if (const auto* x = node.as_floating_point()) {
    out = show_float(x->get());
  } else if (const auto* i = node.as_integer()) {
    out = std::to_string(i->get());
  } else if (const auto* b = node.as_boolean()) {
    out = b->get() ? "true" : "false";
  } else if (const auto* str = node.as_string()) {
    out = show_string(str->get());
  } else if (const auto* array = node.as_array()) {
    out += '[';  // appended, not assigned: GCC 12 reports a false -Wrestrict for out = "["
    for (const toml::node& item : *array) {
      if (out.size() > kShowLimit) break;
      if (out.size() > 1) out += ", ";
      out += depth < 8 ? show(item, depth + 1) : "...";
    }
    out += "]";
  } else if (const auto* table = node.as_table()) {
    out += '{';
    for (auto&& [key, value] : *table) {
      if (out.size() > kShowLimit) break;
      if (out.size() > 1) out += ", ";
      out += show_key(key.str());
      out += " = ";
      out += depth < 8 ? show(value, depth + 1) : "...";
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
  for (auto name : names) {
    if (!out.empty()) out += ", ";
    out += name;
  }
  return out;
}

}  // namespace impact
