#include "scene/overrides.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <utility>

#include "scene/scene_error.hpp"
#include "scene/scene_keys.hpp"
#include "scene/suggest.hpp"
#include "scene/toml_text.hpp"

namespace impact {

void Origins::record(std::string_view table, std::string_view key, std::string change) {
  changes_.push_back({std::string(table), std::string(key), std::move(change)});
}

const std::string& Origins::of(std::string_view table, std::string_view key) const {
  for (auto c = changes_.rbegin(); c != changes_.rend(); ++c)
    if (c->table == table && c->key == key) return c->change;
  return file_;
}

namespace {

std::vector<std::string_view> names_of(const toml::table& table) {
  std::vector<std::string_view> out;
  for (auto&& [name, node] : table) out.push_back(name.str());
  return out;
}

// The [[internal]] table whose name is `name`, or SceneError (through `fail`) naming the variables
// the scene has.
template <class Fail>
toml::table& internal_entry(toml::table& root, const std::string& name, const std::string& file,
                            const Fail& fail) {
  toml::array* entries = root["internal"].as_array();
  if (!entries)
    fail("there is no [[internal]] in " + file +
         ": an internal variable is added in the scene file, with name, initial and rate");
  std::vector<std::string_view> names;
  for (toml::node& entry : *entries)
    if (toml::table* table = entry.as_table())
      if (const auto* n = table->get_as<std::string>("name")) {
        if (n->get() == name) return *table;
        names.push_back(n->get());
      }
  fail("there is no internal variable " + show_string(name) + " in " + file +
       " (its internal variables: " + join(names) + ")" + did_you_mean(name, names));
  throw std::logic_error("unreachable");
}

// Reads `value` as a TOML value (number, boolean, string, array), a bare word as a string, and
// puts it at `key` of `table`.
template <class Fail>
void set_value(toml::table& table, const std::string& key, const std::string& value,
               const Fail& fail) {
  if (find_non_ascii_outside_comments(value) != std::string_view::npos)
    fail("the value '" + cut(value) + "' has a non-ASCII character (a scene's values are ASCII)");
  // A TOML value (number, boolean, string, array); a bare word is read as a string.
  const std::string line = "value = " + value;
  if (const TooDeep deep = find_too_deep(line); deep.at != std::string_view::npos)
    fail("the value has " + deep.what());
  try {
    toml::table parsed = toml::parse(line);
    // One value, not a value and more TOML after it ("0.01\nT = 5" would set time.T too).
    if (parsed.size() != 1) fail("the value '" + cut(value) + "' is not a single TOML value");
    table.insert_or_assign(key, *parsed.get("value"));
  } catch (const toml::parse_error& e) {
    // A bare word is a name (method, stepper, channel): a letter, then letters, digits, _ - or .;
    // anything else (1e400, [1,) is a malformed value, with toml++'s reason.
    const bool word = !value.empty() && std::isalpha(static_cast<unsigned char>(value[0])) &&
                      std::all_of(value.begin(), value.end(), [](unsigned char c) {
                        return std::isalnum(c) || c == '_' || c == '-' || c == '.';
                      });
    if (!word)
      fail("the value '" + cut(value) + "' is not a TOML value (" + cut(e.description()) + ")");
    table.insert_or_assign(key, value);
  }
}

// Whether `path` is a table inside another (force.linear), which --set and --unset address as
// force.linear.k.
bool nested_table(std::string_view path) {
  if (path.find('.') == std::string_view::npos) return false;
  for (const TableSpec& t : scene_tables())
    if (t.name == path) return true;
  return false;
}

// The path table.key split at its last dot when the part before it is a nested table, else at its
// first: {"force.linear", "k"}, {"time", "h"}.
std::pair<std::string, std::string> split_key(const std::string& path) {
  const auto last = path.rfind('.');
  if (last != std::string::npos && nested_table(std::string_view(path).substr(0, last)))
    return {path.substr(0, last), path.substr(last + 1)};
  const auto dot = path.find('.');
  if (dot == std::string::npos) return {path, ""};
  return {path.substr(0, dot), path.substr(dot + 1)};
}

// The table at a path of one or two names, created (empty) where it is missing; nullptr where a
// name on the path is no table.
toml::table* table_at(toml::table& root, const std::string& path, bool create) {
  toml::table* table = &root;
  std::string_view rest = path;
  while (!rest.empty()) {
    const auto dot = rest.find('.');
    const std::string name(rest.substr(0, dot));
    rest = dot == std::string_view::npos ? std::string_view() : rest.substr(dot + 1);
    if (!table->get(name)) {
      if (!create) return nullptr;
      table->insert(name, toml::table{});
    }
    table = table->get(name)->as_table();
    if (!table) return nullptr;
  }
  return table;
}

}  // namespace

void apply_set(toml::table& root, const std::string& assignment, Origins& origins) {
  const std::string change = "--set " + cut(assignment);
  auto fail = [&](const std::string& why) { throw SceneError(change + ": " + why); };
  auto eq = assignment.find('=');
  if (eq == std::string::npos) fail("expected table.key=value");
  std::string path = assignment.substr(0, eq);
  std::string value = assignment.substr(eq + 1);
  // internal.NAME.key: a key of the [[internal]] table of the variable NAME.
  if (const auto internal = internal_key(path)) {
    if (!internal->spec || internal->key == "name") {
      std::vector<std::string_view> keys;
      for (const KeySpec& spec : internal_keys())
        if (spec.key != "name") keys.push_back(spec.key);
      fail("the key of an internal variable is internal.NAME.key with key one of " + join(keys) +
           " (the name addresses the variable; rename it in the scene file), e.g. internal." +
           (internal->name.empty() ? std::string("z") : internal->name) + ".initial" +
           (internal->key.empty() ? "" : did_you_mean(internal->key, keys)));
    }
    set_value(internal_entry(root, internal->name, origins.file(), fail), internal->key, value,
              fail);
    origins.record("internal", internal->name + "." + internal->key, change);
    return;
  }
  const auto [tname, key] = split_key(path);
  if (tname.empty() || key.empty() || key.find('.') != std::string::npos)
    fail(
        "the key must be table.key, e.g. time.h (an internal variable's: internal.NAME.key; the "
        "linear force's: force.linear.k)");

  const std::string outer = tname.substr(0, tname.find('.'));
  if (!root.get(outer)) origins.record(outer, "", change);
  if (outer != tname && !table_at(root, tname, false)) origins.record(tname, "", change);
  toml::table* table = table_at(root, tname, true);
  if (!table) fail(std::string("[").append(tname) + "] is not a table");
  set_value(*table, key, value, fail);
  origins.record(tname, key, change);
}

void apply_unset(toml::table& root, const std::string& path, const std::vector<std::string>& sets,
                 Origins& origins) {
  const std::string change = "--unset " + cut(path);
  auto fail = [&](const std::string& why) { throw SceneError(change + ": " + why); };
  for (const auto& set : sets)
    if (set.substr(0, set.find('=')) == path) fail("--set " + cut(set) + " sets it too; give one");
  // internal.NAME: the variable NAME (its [[internal]] table); its keys are all required.
  if (const auto internal = internal_key(path)) {
    if (!internal->key.empty())
      fail("every [[internal]] table needs name, initial and rate: --set " + path +
           "=... changes it, --unset internal." + internal->name + " removes the variable");
    if (origins.of("internal", internal->name) == change) return;  // removed already
    internal_entry(root, internal->name, origins.file(), fail);
    toml::array& entries = *root["internal"].as_array();
    for (auto entry = entries.begin(); entry != entries.end(); ++entry)
      if (const toml::table* table = entry->as_table())
        if (const auto* n = table->get_as<std::string>("name"); n && n->get() == internal->name) {
          entries.erase(entry);
          break;
        }
    if (entries.empty()) root.erase("internal");
    origins.record("internal", internal->name, change);
    return;
  }
  const auto dot = path.find('.');
  const auto [tname, key] = split_key(path);
  if (tname.empty() || path.find('=') != std::string::npos ||
      (dot != std::string::npos && (key.empty() || key.find('.') != std::string::npos)))
    fail("expected table.key or table, e.g. floor.cor, force or force.linear.k");

  const auto names = names_of;
  // A second --unset of the same key or table has nothing left to remove, and need not.
  const bool removed =
      origins.of(tname, key) == change || origins.of(tname) == "--unset " + cut(tname);
  if (key.empty()) {
    if (!root.erase(tname)) {
      if (removed) return;
      fail("there is no [" + show_key(tname) + "] in " + origins.file() +
           did_you_mean(tname, names(root)));
    }
  } else if (toml::table* table = table_at(root, tname, false); !table || !table->erase(key)) {
    if (removed) return;
    fail(table ? "there is no " + show_key(tname) + "." + show_key(key) + " in " + origins.file() +
                     did_you_mean(key, names(*table), tname + ".")
               : "there is no [" + show_key(tname) + "] in " + origins.file() +
                     did_you_mean(tname, names(root)));
  }
  origins.record(tname, key, change);
}

}  // namespace impact
