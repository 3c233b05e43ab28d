#include "scene/read_scene.hpp"

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

#include "scene/method_keys.hpp"
#include "scene/overrides.hpp"
#include "scene/toml_text.hpp"

namespace impact {
namespace {

// 2^53: the largest step count for which every l and l*h are exact in double precision.
constexpr double kMaxSteps = 9007199254740992.0;

// A scene is a few hundred bytes; a file this large is not one (and /dev/zero would never end).
constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 20;

// table.key as a message names it.
std::string key_name(std::string_view table, std::string_view key) {
  return show_key(table) + "." + show_key(key);
}

class Reader {
 public:
  Reader(const toml::table& root, const Origins& origins) : root_(root), origins_(origins) {}

  // A message about table.key, naming where it came from: the file or a --set.
  [[noreturn]] void fail(std::string_view table, std::string_view key,
                         const std::string& what) const {
    throw SceneError(origins_.of(table, key) + ": " + key_name(table, key) + ": " + what);
  }
  // A message about a table (`name` shows it: "[time]", or the table's value).
  [[noreturn]] void fail_table(std::string_view table, const std::string& name,
                               const std::string& what) const {
    throw SceneError(origins_.of(table) + ": " + name + ": " + what);
  }
  [[noreturn]] void fail_value(std::string_view table, std::string_view key, const toml::node& node,
                               const std::string& allowed) const {
    throw SceneError(origins_.of(table, key) + ": " + key_name(table, key) + " = " + show(node) +
                     ": " + allowed);
  }
  const Origins& origins() const { return origins_; }

  // Every table and key present must be one we know (catches typos).
  void only(const toml::table& table, std::string_view where,
            const std::vector<std::string_view>& allowed) const {
    for (auto&& [key, node] : table) {
      bool known = false;
      for (auto a : allowed) known = known || a == key.str();
      if (!known) {
        if (where.empty())
          fail_table(key.str(), show_key(key.str()),
                     "unknown table (allowed: " + join(allowed) + ")");
        // A key also shows its value, which helps to spot what the typo meant.
        fail_value(where, key.str(), node,
                   "unknown key (allowed in [" + std::string(where) + "]: " + join(allowed) + ")");
      }
    }
  }

  const toml::table* table(std::string_view name, bool required) const {
    const toml::node* node = root_.get(name);
    if (!node) {
      if (required) fail_table(name, "[" + std::string(name) + "]", "required table is missing");
      return nullptr;
    }
    if (!node->is_table())
      fail_table(name, std::string(name) + " = " + show(*node), "must be a table");
    return node->as_table();
  }

  std::optional<double> number(const toml::table* t, std::string_view tname,
                               std::string_view key) const {
    if (!t) return std::nullopt;
    const toml::node* node = t->get(key);
    if (!node) return std::nullopt;
    double x;
    if (node->is_integer()) {
      x = static_cast<double>(node->as_integer()->get());
    } else if (node->is_floating_point()) {
      x = node->as_floating_point()->get();
    } else {
      fail_value(tname, key, *node, "must be a number");
    }
    if (!std::isfinite(x)) fail_value(tname, key, *node, "must be a finite number");
    return x;
  }

  double required_number(const toml::table* t, std::string_view tname, std::string_view key) const {
    auto x = number(t, tname, key);
    if (!x) fail(tname, key, "required key is missing");
    return *x;
  }

 private:
  const toml::table& root_;
  const Origins& origins_;
};

// [initial], [floor] and [force] into the model and the initial state.
void read_physics(const Reader& r, Scene& scene) {
  const toml::table* initial = r.table("initial", true);
  r.only(*initial, "initial", {"u0", "v0"});
  scene.initial.u = r.required_number(initial, "initial", "u0");
  scene.initial.v = r.required_number(initial, "initial", "v0");

  if (const toml::table* floor = r.table("floor", false)) {
    r.only(*floor, "floor", {"phi", "cor"});
    scene.model.phi = r.number(floor, "floor", "phi").value_or(0.0);
    scene.model.cor = r.number(floor, "floor", "cor");
    if (scene.model.cor && (*scene.model.cor < 0.0 || *scene.model.cor > 1.0))
      r.fail_value("floor", "cor", *floor->get("cor"), "must be in [0, 1]");
  }
  if (scene.initial.u < scene.model.phi)
    r.fail_value("initial", "u0", *initial->get("u0"),
                 "must be >= floor.phi = " + show_number(scene.model.phi) +
                     " (the particle starts above the floor)");

  if (const toml::table* force = r.table("force", false)) {
    r.only(*force, "force", {"f"});
    scene.model.f = r.required_number(force, "force", "f");
  }
}

void read_time(const Reader& r, Scene& scene) {
  const toml::table* time = r.table("time", true);
  r.only(*time, "time", {"T", "h"});
  scene.T = r.required_number(time, "time", "T");
  const double h = r.required_number(time, "time", "h");
  if (scene.T <= 0.0) r.fail_value("time", "T", *time->get("T"), "must be > 0");
  if (h <= 0.0) r.fail_value("time", "h", *time->get("h"), "must be > 0");
  if (h > scene.T)
    r.fail_value("time", "h", *time->get("h"), "must be <= time.T = " + show(*time->get("T")));
  const double ratio = scene.T / h;
  if (!(ratio <= kMaxSteps))
    r.fail_value("time", "h", *time->get("h"),
                 "T/h = " + show_number(ratio) +
                     " steps is too many to count exactly (at most 2^53 = 9007199254740992)");
  scene.grid = Grid::covering(scene.T, h);
}

// method.name: the method whose keys read_method_keys() reads once the rest is valid.
const MethodInfo& read_method_name(const Reader& r) {
  const toml::table* method = r.table("method", true);
  const toml::node* name = method->get("name");
  if (!name) r.fail("method", "name", "required key is missing");
  if (!name->is_string()) r.fail_value("method", "name", *name, "must be a string");
  const MethodInfo* info = find_method(name->as_string()->get());
  if (!info) {
    std::vector<std::string_view> names;
    for (const auto& m : methods()) names.push_back(m.name);
    r.fail_value("method", "name", *name, "unknown method (allowed: " + join(names) + ")");
  }
  return *info;
}

void read_channels(const Reader& r, const toml::node& channels, const MethodInfo& method,
                   OutputSpec& output) {
  const toml::array* list = channels.as_array();
  if (!list || list->empty())
    r.fail_value("output", "channels", channels, "must be a non-empty array of channel names");
  output.channels.clear();
  std::vector<std::string_view> allowed{"u", "v", "N", "E"};
  if (method.has_iterations) allowed.push_back("iterations");
  for (const toml::node& item : *list) {
    const toml::value<std::string>* s = item.as_string();
    bool ok = false;
    if (s) {
      for (Channel c : {Channel::u, Channel::v, Channel::N, Channel::E, Channel::iterations}) {
        if (channel_name(c) != s->get()) continue;
        if (c == Channel::iterations && !method.has_iterations) break;
        for (Channel seen : output.channels)
          if (seen == c)
            r.fail_value("output", "channels", item, "is listed twice (at most once each)");
        output.channels.push_back(c);
        ok = true;
      }
    }
    if (!ok)
      r.fail_value("output", "channels", item,
                   "is not a channel method '" + std::string(method.name) +
                       "' can produce (allowed: " + join(allowed) + ")");
  }
}

void read_output(const Reader& r, const MethodInfo& method, Scene& scene) {
  if (const toml::table* output = r.table("output", false)) {
    r.only(*output, "output", {"channels", "every"});
    if (const toml::node* every = output->get("every")) {
      if (!every->is_integer() || every->as_integer()->get() < 1)
        r.fail_value("output", "every", *every, "must be an integer >= 1");
      scene.output.every = every->as_integer()->get();
    }
    if (const toml::node* channels = output->get("channels"))
      read_channels(r, *channels, method, scene.output);
  }
  for (Channel c : scene.output.channels)
    if (c == Channel::E && !std::isfinite(energy(scene.model, scene.initial)))
      r.fail("output", "channels",
             "E: the initial energy v0^2/2 - f u0 (3-1) is beyond the double range (v0 = " +
                 show_number(scene.initial.v) + ", f = " + show_number(scene.model.f) +
                 ", u0 = " + show_number(scene.initial.u) + ")");
}

Scene build(const toml::table& root, const Origins& origins) {
  const Reader r(root, origins);
  r.only(root, "", {"initial", "floor", "force", "time", "method", "output"});
  Scene scene;
  read_physics(r, scene);
  read_time(r, scene);
  const MethodInfo& method = read_method_name(r);
  read_output(r, method, scene);
  // Compliance has no impact law to apply a COR to: refuse rather than silently run elastic.
  if (scene.model.cor && !method.takes_cor) {
    const std::string& named = origins.of("method", "name");
    r.fail_value("floor", "cor", *root.get("floor")->as_table()->get("cor"),
                 "method '" + std::string(method.name) + "'" +
                     (named == origins.of("floor", "cor") ? "" : " (" + named + ")") +
                     " has no restitution law (its compliance contact is elastic); remove "
                     "floor.cor or choose direct, fb_newton, moreau_jean or exact");
  }
  scene.method = read_method_keys(*root.get("method")->as_table(), origins, method);
  return scene;
}

// The TOML document, or SceneError with the parser's message and the line and column it names.
toml::table parse_toml(std::string_view text, const std::string& source) {
  // TOML asks for a valid UTF-8 document, which may start with a byte-order mark (Windows editors
  // write one): skipped, as toml++ does, so that columns on line 1 count what an editor shows.
  constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  if (const std::size_t at = find_non_ascii_outside_comments(text); at != std::string_view::npos) {
    if (text.substr(at).starts_with(kByteOrderMark))
      throw SceneError(source + ":" + line_and_column(text, at) +
                       ": not a valid scene: a UTF-8 byte-order mark (U+FEFF) is allowed only at "
                       "the start of the file");
    char byte[8];
    std::snprintf(byte, sizeof byte, "0x%02x", static_cast<unsigned char>(text[at]));
    throw SceneError(source + ":" + line_and_column(text, at) +
                     ": not a valid scene: non-ASCII byte " + byte +
                     " outside a comment (a scene's keys and values are ASCII)");
  }
  if (const TooDeep deep = find_too_deep(text); deep.at != std::string_view::npos)
    throw SceneError(source + ":" + line_and_column(text, deep.at) +
                     ": not a valid scene: " + deep.what());
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << source;
    if (e.source().begin.line > 0)
      msg << ":" << e.source().begin.line << ":" << e.source().begin.column;
    msg << ": not a valid TOML scene: " << cut(e.description());
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
  Origins origins(source);
  for (const auto& o : overrides) apply_set(root, o, origins);
  return build(root, origins);
}

}  // namespace

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  return parse_with(parse_toml(read_scene_file(path), path), path, overrides);
}

Scene parse_scene(std::string_view text, const std::string& source,
                  const std::vector<std::string>& overrides) {
  return parse_with(parse_toml(text, source), source, overrides);
}

Run load_run(const std::string& path, const std::vector<std::string>& overrides) {
  Scene scene = load_scene(path, overrides);
  try {
    AnyStepper stepper = make_stepper(scene);
    return {std::move(scene), std::move(stepper)};
  } catch (const std::invalid_argument& e) {
    throw SceneError(path + ": " + e.what());  // the reader's ranges should have caught it
  }
}

}  // namespace impact
