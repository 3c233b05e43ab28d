#include "impact/scene.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <sstream>

#include "impact/registry.hpp"

namespace impact {
namespace {

// 2^53: the largest step count for which every l and l*h are exact in double precision.
constexpr double kMaxSteps = 9007199254740992.0;

// A scene is a few hundred bytes; a file this large is not one (and /dev/zero would never end).
constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 20;

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

// The shortest decimal that reads back as x (1e-15, not toml++'s 1.0000000000000001e-15).
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

std::string show_number(double x) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

// A string value in TOML syntax: 'literal' when it can be, else "basic" with escapes.
std::string show_string(std::string_view text) {
  bool literal = true;
  for (unsigned char c : text) literal = literal && c >= 0x20 && c != 0x7f && c != '\'';
  if (literal) return "'" + std::string(text) + "'";
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

// Messages show at most this much of a value.
constexpr std::size_t kShowLimit = 200;

// A value as it would be written in TOML, for messages. Written here, not by toml++: its formatter
// lays out arrays by converting log10 of each number to size_t, which is undefined for nan, inf,
// |x| < 0.1 and INT64_MIN (found by tests/fuzz), and classifies non-ASCII characters of strings
// with the lookup of find_non_ascii_outside_comments().
std::string show(const toml::node& node, int depth = 0) {
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

class Reader {
 public:
  Reader(const toml::table& root, const std::string& source) : root_(root), source_(source) {}

  [[noreturn]] void fail(std::string_view key, const std::string& what) const {
    throw SceneError(source_ + ": " + std::string(key) + ": " + what);
  }
  [[noreturn]] void fail_value(std::string_view key, const toml::node& node,
                               const std::string& allowed) const {
    throw SceneError(source_ + ": " + std::string(key) + " = " + show(node) + ": " + allowed);
  }

  // Every table and key present must be one we know (catches typos).
  void only(const toml::table& table, std::string_view where,
            const std::vector<std::string_view>& allowed) const {
    for (auto&& [key, node] : table) {
      bool known = false;
      for (auto a : allowed) known = known || a == key.str();
      if (!known) {
        if (where.empty())
          fail(printable(key.str()), "unknown table (allowed: " + join(allowed) + ")");
        // A key also shows its value, which helps to spot what the typo meant.
        fail_value(std::string(where) + "." + printable(key.str()), node,
                   "unknown key (allowed in [" + std::string(where) + "]: " + join(allowed) + ")");
      }
    }
  }

  const toml::table* table(std::string_view name, bool required) const {
    const toml::node* node = root_.get(name);
    if (!node) {
      if (required) fail("[" + std::string(name) + "]", "required table is missing");
      return nullptr;
    }
    if (!node->is_table()) fail_value(name, *node, "must be a table");
    return node->as_table();
  }

  std::optional<double> number(const toml::table* t, std::string_view tname,
                               std::string_view key) const {
    if (!t) return std::nullopt;
    const toml::node* node = t->get(key);
    if (!node) return std::nullopt;
    std::string full = std::string(tname) + "." + std::string(key);
    double x;
    if (node->is_integer()) {
      x = static_cast<double>(node->as_integer()->get());
    } else if (node->is_floating_point()) {
      x = node->as_floating_point()->get();
    } else {
      fail_value(full, *node, "must be a number");
    }
    if (!std::isfinite(x)) fail_value(full, *node, "must be a finite number");
    return x;
  }

  double required_number(const toml::table* t, std::string_view tname, std::string_view key) const {
    auto x = number(t, tname, key);
    if (!x) fail(std::string(tname) + "." + std::string(key), "required key is missing");
    return *x;
  }

 private:
  const toml::table& root_;
  const std::string& source_;
};

void apply_override(toml::table& root, const std::string& assignment, const std::string& source) {
  auto fail = [&](const std::string& why) {
    throw SceneError(source + ": --set " + assignment + ": " + why);
  };
  auto eq = assignment.find('=');
  if (eq == std::string::npos) fail("expected table.key=value");
  std::string path = assignment.substr(0, eq);
  std::string value = assignment.substr(eq + 1);
  auto dot = path.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == path.size() ||
      path.find('.', dot + 1) != std::string::npos)
    fail("the key must be table.key, e.g. time.h");
  std::string tname = path.substr(0, dot), key = path.substr(dot + 1);

  toml::node_view<toml::node> slot = root[tname];
  if (!slot) root.insert(tname, toml::table{});
  toml::table* table = root[tname].as_table();
  if (!table) fail("[" + tname + "] is not a table");

  if (find_non_ascii_outside_comments(value) != std::string_view::npos)
    fail("the value '" + value + "' has a non-ASCII character (a scene's values are ASCII)");
  // A TOML value (number, boolean, string, array); a bare word is read as a string.
  try {
    toml::table parsed = toml::parse("value = " + value);
    // One value, not a value and more TOML after it ("0.01\nT = 5" would set time.T too).
    if (parsed.size() != 1) fail("the value '" + value + "' is not a single TOML value");
    table->insert_or_assign(key, *parsed.get("value"));
  } catch (const toml::parse_error& e) {
    // A bare word is a name (method, stepper, channel): a letter, then letters, digits, _ - or .;
    // anything else (1e400, [1,) is a malformed value, with toml++'s reason.
    const bool word = !value.empty() && std::isalpha(static_cast<unsigned char>(value[0])) &&
                      std::all_of(value.begin(), value.end(), [](unsigned char c) {
                        return std::isalnum(c) || c == '_' || c == '-' || c == '.';
                      });
    if (!word)
      fail("the value '" + value + "' is not a TOML value (" + std::string(e.description()) + ")");
    table->insert_or_assign(key, value);
  }
}

Scene build(toml::table root, const std::string& source) {
  Reader r(root, source);
  r.only(root, "", {"initial", "floor", "force", "time", "method", "output"});

  Scene scene;
  scene.source = source;

  const toml::table* initial = r.table("initial", true);
  r.only(*initial, "initial", {"u0", "v0"});
  scene.initial.u = r.required_number(initial, "initial", "u0");
  scene.initial.v = r.required_number(initial, "initial", "v0");

  if (const toml::table* floor = r.table("floor", false)) {
    r.only(*floor, "floor", {"phi", "cor"});
    scene.model.phi = r.number(floor, "floor", "phi").value_or(0.0);
    scene.model.cor = r.number(floor, "floor", "cor");
    if (scene.model.cor && (*scene.model.cor < 0.0 || *scene.model.cor > 1.0))
      r.fail_value("floor.cor", *floor->get("cor"), "must be in [0, 1]");
  }
  if (scene.initial.u < scene.model.phi)
    r.fail_value("initial.u0", *initial->get("u0"),
                 "must be >= floor.phi = " + show_number(scene.model.phi) +
                     " (the particle starts above the floor)");

  if (const toml::table* force = r.table("force", false)) {
    r.only(*force, "force", {"f"});
    scene.model.f = r.required_number(force, "force", "f");
  }

  const toml::table* time = r.table("time", true);
  r.only(*time, "time", {"T", "h"});
  scene.T = r.required_number(time, "time", "T");
  scene.grid.h = r.required_number(time, "time", "h");
  if (scene.T <= 0.0) r.fail_value("time.T", *time->get("T"), "must be > 0");
  if (scene.grid.h <= 0.0) r.fail_value("time.h", *time->get("h"), "must be > 0");
  if (scene.grid.h > scene.T)
    r.fail_value("time.h", *time->get("h"), "must be <= time.T = " + show(*time->get("T")));
  double ratio = scene.T / scene.grid.h;
  if (!(ratio <= kMaxSteps))
    r.fail_value("time.h", *time->get("h"),
                 "T/h = " + show_number(ratio) +
                     " steps is too many to count exactly (at most 2^53 = 9007199254740992)");
  double rounded = std::round(ratio);
  scene.grid.steps = static_cast<std::int64_t>(
      std::abs(ratio - rounded) <= 1e-9 * rounded ? rounded : std::ceil(ratio));

  const toml::table* method = r.table("method", true);
  const toml::node* name = method->get("name");
  if (!name) r.fail("method.name", "required key is missing");
  if (!name->is_string()) r.fail_value("method.name", *name, "must be a string");
  scene.method = name->as_string()->get();
  const MethodInfo* info = find_method(scene.method);
  if (!info) {
    std::vector<std::string_view> names;
    for (const auto& m : methods()) names.push_back(m.name);
    r.fail_value("method.name", *name, "unknown method (allowed: " + join(names) + ")");
  }
  scene.method_params = *method;

  if (const toml::table* output = r.table("output", false)) {
    r.only(*output, "output", {"channels", "every"});
    if (const toml::node* every = output->get("every")) {
      if (!every->is_integer() || every->as_integer()->get() < 1)
        r.fail_value("output.every", *every, "must be an integer >= 1");
      scene.output.every = every->as_integer()->get();
    }
    if (const toml::node* channels = output->get("channels")) {
      const toml::array* list = channels->as_array();
      if (!list || list->empty())
        r.fail_value("output.channels", *channels, "must be a non-empty array of channel names");
      scene.output.channels.clear();
      std::vector<std::string_view> allowed{"u", "v", "N", "E"};
      if (info->has_iterations) allowed.push_back("iterations");
      for (const toml::node& item : *list) {
        const toml::value<std::string>* s = item.as_string();
        bool ok = false;
        if (s) {
          for (Channel c : {Channel::u, Channel::v, Channel::N, Channel::E, Channel::iterations}) {
            if (channel_name(c) != s->get()) continue;
            if (c == Channel::iterations && !info->has_iterations) break;
            for (Channel seen : scene.output.channels)
              if (seen == c)
                r.fail_value("output.channels", item, "is listed twice (at most once each)");
            scene.output.channels.push_back(c);
            ok = true;
          }
        }
        if (!ok)
          r.fail_value("output.channels", item,
                       "is not a channel method '" + scene.method +
                           "' can produce (allowed: " + join(allowed) + ")");
      }
    }
  }
  for (Channel c : scene.output.channels)
    if (c == Channel::E && !std::isfinite(energy(scene.model, scene.initial)))
      r.fail("output.channels",
             "E: the initial energy v0^2/2 - f u0 (3-1) is beyond the double range (v0 = " +
                 show_number(scene.initial.v) + ", f = " + show_number(scene.model.f) +
                 ", u0 = " + show_number(scene.initial.u) + ")");
  scene.document = std::move(root);
  return scene;
}

// The TOML document, or SceneError with the parser's message and the line and column it names.
toml::table parse_toml(std::string_view text, const std::string& source) {
  if (const std::size_t at = find_non_ascii_outside_comments(text); at != std::string_view::npos) {
    // Line and column as toml++ counts them: the column in characters, not bytes.
    const std::size_t newline = text.rfind('\n', at);
    const std::size_t line_start = newline == std::string_view::npos ? 0 : newline + 1;
    const std::size_t line =
        1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + at, '\n'));
    std::size_t column = 1;
    for (std::size_t i = line_start; i < at; ++i)
      column += (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;  // not a continuation byte
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(text[at]));
    throw SceneError(source + ":" + std::to_string(line) + ":" + std::to_string(column) +
                     ": not a valid scene: non-ASCII byte " + byte +
                     " outside a comment (a scene's keys and values are ASCII)");
  }
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << source;
    if (e.source().begin.line > 0)
      msg << ":" << e.source().begin.line << ":" << e.source().begin.column;
    msg << ": not a valid TOML scene: " << e.description();
    throw SceneError(msg.str());
  }
}

// The whole file, read by hand rather than by toml::parse_file, so that a pipe (/dev/stdin) works,
// a directory or a device that never ends (/dev/zero) is rejected, and an error says why.
std::string read_scene_file(const std::string& path) {
  const int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw SceneError(path + ": cannot open the scene file: " + std::strerror(errno));
  struct stat info;
  if (fstat(fd, &info) == 0 && S_ISDIR(info.st_mode)) {
    close(fd);
    throw SceneError(path + ": is a directory, not a scene file");
  }
  std::string text;
  char chunk[65536];
  for (;;) {
    const ssize_t n = read(fd, chunk, sizeof chunk);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      close(fd);
      throw SceneError(path + ": cannot read the scene file: " + std::strerror(err));
    }
    text.append(chunk, static_cast<std::size_t>(n));
    if (text.size() > kMaxSceneBytes) {
      close(fd);
      throw SceneError(path + ": longer than " + std::to_string(kMaxSceneBytes) +
                       " bytes: not a scene file");
    }
  }
  close(fd);
  return text;
}

Scene parse_with(toml::table root, const std::string& source,
                 const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) apply_override(root, o, source);
  Scene scene = build(std::move(root), source);
  make_stepper(scene);  // the solver validates its own [method] keys now, before any work starts
  return scene;
}

}  // namespace

std::string_view channel_name(Channel c) {
  switch (c) {
    case Channel::u:
      return "u";
    case Channel::v:
      return "v";
    case Channel::N:
      return "N";
    case Channel::E:
      return "E";
    case Channel::iterations:
      return "iterations";
  }
  return "?";
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_with(parse_toml(read_scene_file(path), path), path, overrides);
}

Scene parse_scene(std::string_view text, const std::string& source,
                  const std::vector<std::string>& overrides) {
  return parse_with(parse_toml(text, source), source, overrides);
}

const toml::node* MethodParams::find(std::string_view key) {
  read_.emplace_back(key);
  return scene_.method_params.get(key);
}

double MethodParams::number(std::string_view key, double fallback, double lo, double hi,
                            bool lo_open) {
  const toml::node* node = find(key);
  if (!node) return fallback;
  std::string full = "method." + std::string(key);
  double x;
  if (node->is_integer())
    x = static_cast<double>(node->as_integer()->get());
  else if (node->is_floating_point())
    x = node->as_floating_point()->get();
  else
    throw SceneError(scene_.source + ": " + full + " = " + show(*node) + ": must be a number");
  bool ok = std::isfinite(x) && (lo_open ? x > lo : x >= lo) && x <= hi;
  if (!ok) {
    std::ostringstream range;
    range << "must be in " << (lo_open ? "(" : "[") << lo << ", " << hi << "]";
    throw SceneError(scene_.source + ": " + full + " = " + show(*node) + ": " + range.str());
  }
  return x;
}

std::int64_t MethodParams::integer(std::string_view key, std::int64_t fallback, std::int64_t lo,
                                   std::int64_t hi) {
  const toml::node* node = find(key);
  if (!node) return fallback;
  if (!node->is_integer() || node->as_integer()->get() < lo || node->as_integer()->get() > hi)
    throw SceneError(scene_.source + ": method." + std::string(key) + " = " + show(*node) +
                     ": must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) +
                     "]");
  return node->as_integer()->get();
}

std::string MethodParams::choice(std::string_view key, std::string_view fallback,
                                 const std::vector<std::string_view>& allowed) {
  const toml::node* node = find(key);
  if (!node) return std::string(fallback);
  if (node->is_string())
    for (auto a : allowed)
      if (a == node->as_string()->get()) return std::string(a);
  throw SceneError(scene_.source + ": method." + std::string(key) + " = " + show(*node) +
                   ": must be one of " + join(allowed));
}

void MethodParams::reject_unread() const {
  for (auto&& [key, node] : scene_.method_params) {
    bool read = false;
    for (const auto& r : read_) read = read || r == key.str();
    if (!read) {
      std::vector<std::string_view> names(read_.begin(), read_.end());
      throw SceneError(scene_.source + ": method." + std::string(key.str()) + " = " + show(node) +
                       ": unknown key for method '" + scene_.method + "' (allowed: " + join(names) +
                       ")");
    }
  }
}

}  // namespace impact
