#include "impact/scene.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

#include "impact/registry.hpp"

namespace impact {
namespace {

// 2^53: the largest step count for which every l and l*h are exact in double precision.
constexpr double kMaxSteps = 9007199254740992.0;

// The shortest decimal that reads back as x (1e-15, not toml++'s 1.0000000000000001e-15).
std::string show_number(double x) {
  char buf[64];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, x).ptr);
}

std::string show(const toml::node& node) {
  if (const toml::value<double>* x = node.as_floating_point()) return show_number(x->get());
  std::ostringstream out;
  node.visit([&](auto&& v) { out << v; });
  return out.str();
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
          fail(std::string(key.str()), "unknown table (allowed: " + join(allowed) + ")");
        // A key also shows its value, which helps to spot what the typo meant.
        fail_value(std::string(where) + "." + std::string(key.str()), node,
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

  // A TOML value (number, boolean, string, array); a bare word is read as a string.
  try {
    toml::table parsed = toml::parse("value = " + value);
    table->insert_or_assign(key, *parsed.get("value"));
  } catch (const toml::parse_error&) {
    if (value.empty() || value.find_first_of("\"'[]{}=\n") != std::string::npos)
      fail("the value '" + value + "' is not a TOML value");
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
  scene.document = std::move(root);
  return scene;
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
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << path;
    if (e.source().begin.line > 0)
      msg << ":" << e.source().begin.line << ":" << e.source().begin.column;
    msg << ": not a valid TOML scene: " << e.description();
    throw SceneError(msg.str());
  }
  return parse_with(std::move(root), path, overrides);
}

Scene parse_scene(std::string_view text, const std::string& source,
                  const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw SceneError(source + ": not a valid TOML scene: " + std::string(e.description()));
  }
  return parse_with(std::move(root), source, overrides);
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
