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

#include "impact/forces/work_energy.hpp"
#include "impact/format.hpp"
#include "scene/bonding_keys.hpp"
#include "scene/force_keys.hpp"
#include "scene/internal_keys.hpp"
#include "scene/key_reader.hpp"
#include "scene/method_keys.hpp"
#include "scene/overrides.hpp"
#include "scene/scene_document.hpp"
#include "scene/scene_keys.hpp"
#include "scene/suggest.hpp"
#include "scene/toml_text.hpp"
#include "scene/validate.hpp"

namespace impact {
namespace {

// A scene is a few hundred bytes; a file this large is not one (and /dev/zero would never end).
constexpr std::size_t kMaxSceneBytes = std::size_t{1} << 20;

void read_channels(const KeyReader& r, const toml::node& channels, const MethodInfo& method,
                   const Model& model, Output& output) {
  const toml::array* list = channels.as_array();
  if (!list || list->empty())
    r.fail_value("output", "channels", channels, "must be a non-empty array of channel names");
  output.channels.clear();
  std::vector<std::string_view> allowed;
  std::vector<Channel> known;
  for (const ChannelInfo& c : impact::channels()) known.push_back(c.channel);
  for (std::size_t i = 0; i < model.internal.size(); ++i) known.push_back(internal_channel(i));
  if (bonded(model))
    for (const ChannelInfo& c : bonding_channels()) known.push_back(c.channel);
  for (Channel c : known)
    if (can_write(method, c)) allowed.push_back(channel_name(c, model));
  for (const toml::node& item : *list) {
    const toml::value<std::string>* s = item.as_string();
    bool ok = false;
    if (s) {
      for (Channel c : known) {
        if (channel_name(c, model) != s->get() || !can_write(method, c)) continue;
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
                       "' can produce (allowed: " + join(allowed) + ")" +
                       (s ? did_you_mean(s->get(), allowed) : ""));
  }
}

// The value of table.key, which the reader has seen.
const toml::node& node_at(const toml::table& root, std::string_view table, std::string_view key) {
  return *root.get(table)->as_table()->get(key);
}

// What the method refuses (capabilities.hpp), as the value of the key it names. A refusal of
// another key than method.name names the method; where the method came from is said too when it is
// not where that key came from ("method 'penalty' (--set method.name=penalty) has no restitution
// law").
[[noreturn]] void fail_refused(const KeyReader& r, const toml::table& root, const Scene& scene,
                               const Refusal& refused) {
  std::string message = refused.message;
  const std::string& named = r.origins().of("method", "name");
  const std::string method = "method '" + std::string(method_name(scene.method)) + "'";
  if (message.starts_with(method) && named != r.origins().of(refused.table, refused.key))
    message.insert(method.size(), " (" + named + ")");
  r.fail_value(refused.table, refused.key, node_at(root, refused.table, refused.key), message);
}

// Every table against the key specs (scene_keys.hpp), then what no single key can check: u0 >=
// phi, h <= T and T/h countable, the channels the method can write, E representable. The method's
// own keys, then what the method refuses of the whole problem (refusal()), come before the
// channels and the checks that join keys.
Scene build(const toml::table& root, const Origins& origins) {
  const KeyReader r(root, origins);
  std::vector<std::string_view> tables;
  for (const TableSpec& t : scene_tables())
    if (t.name.find('.') == std::string_view::npos)
      tables.push_back(t.name);  // force.linear: a key
  tables.push_back("internal");  // an array of tables (internal_keys.hpp)
  r.only(root, "", tables);
  Scene scene;
  for (const TableSpec& t : scene_tables()) {
    const toml::table* table = r.table(t.name, t.required);
    if (!table) continue;
    if (t.name != "method") r.only(*table, t.name, key_names(t.name));  // method: by its keys
    for (const KeySpec& spec : scene_keys())
      if (spec.table == t.name && spec.set) r.read(*table, spec, scene);
  }

  read_internal(r, root, scene);
  check_force(r, root, scene);
  check_bonding(r, root, scene);
  read_method_keys(r, *root.get("method")->as_table(), scene);
  // What the method refuses, before the channels it cannot write for that reason (an internal
  // variable's) are named.
  if (const auto refused = refusal(scene.method, scene.model, scene.grid.h))
    fail_refused(r, root, scene, *refused);
  const MethodInfo& method = method_info(scene.method);
  if (const toml::node* channels = root.at_path("output.channels").node())
    read_channels(r, *channels, method, scene.model, scene.output);
  const ShowKey as_typed = [&](std::string_view table, std::string_view key) {
    return show(node_at(root, table, key));
  };
  if (const auto issue = cross_check(scene, as_typed)) {
    if (issue->with_value)
      r.fail_value(issue->table, issue->key, node_at(root, issue->table, issue->key), issue->what);
    r.fail(issue->table, issue->key, issue->what);
  }
  scene.grid = Grid::covering(scene.T, scene.grid.h);
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

Scene parse_with(toml::table root, const std::string& source,
                 const std::vector<std::string>& overrides,
                 const std::vector<std::string>& unsets) {
  Origins origins(source);
  for (const auto& u : unsets) apply_unset(root, u, overrides, origins);
  for (const auto& o : overrides) apply_set(root, o, origins);
  return build(root, origins);
}

}  // namespace

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

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides,
                 const std::vector<std::string>& unsets) {
  return parse_with(parse_toml(read_scene_file(path), path), path, overrides, unsets);
}

Scene parse_scene(std::string_view text, const std::string& source,
                  const std::vector<std::string>& overrides,
                  const std::vector<std::string>& unsets) {
  return parse_with(parse_toml(text, source), source, overrides, unsets);
}

Scene read_scene(const SceneFile& file, const SceneEdits& edits) {
  return load_scene(file.path.string(), edits.set, edits.unset);
}

Scene read_scene(const SceneText& text, const SceneEdits& edits) {
  return parse_scene(text.text, text.source, edits.set, edits.unset);
}

namespace {

// The stepper of a scene the reader accepted, `text` kept for the record.
Run with_stepper(Scene scene, const std::string& source, std::string text) {
  try {
    AnyStepper stepper = make_stepper(scene);
    return {std::move(scene), std::move(stepper), std::move(text)};
  } catch (const std::invalid_argument& e) {
    // the reader's ranges should have caught it
    throw SceneError(source + ": " + e.what());
  }
}

}  // namespace

Run load_run(const SceneText& text, const std::vector<std::string>& overrides,
             const std::vector<std::string>& unsets) {
  return with_stepper(parse_scene(text.text, text.source, overrides, unsets), text.source,
                      std::string(text.text));
}

Run load_run(const SceneDocument& document, const SceneEdits& edits) {
  return with_stepper(parse_with(document.root, document.source, edits.set, edits.unset),
                      document.source, "");
}

Run load_run(const std::string& path, const std::vector<std::string>& overrides,
             const std::vector<std::string>& unsets) {
  const std::string text = read_scene_file(path);
  return load_run(SceneText{text, path}, overrides, unsets);
}

}  // namespace impact
