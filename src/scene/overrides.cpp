#include "scene/overrides.hpp"

#include <algorithm>
#include <cctype>

#include "scene/scene_error.hpp"
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

void apply_set(toml::table& root, const std::string& assignment, Origins& origins) {
  const std::string change = "--set " + cut(assignment);
  auto fail = [&](const std::string& why) { throw SceneError(change + ": " + why); };
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
  if (!slot) {
    root.insert(tname, toml::table{});
    origins.record(tname, "", change);
  }
  toml::table* table = root[tname].as_table();
  if (!table) fail(std::string("[").append(show_key(tname)) + "] is not a table");

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
    table->insert_or_assign(key, *parsed.get("value"));
  } catch (const toml::parse_error& e) {
    // A bare word is a name (method, stepper, channel): a letter, then letters, digits, _ - or .;
    // anything else (1e400, [1,) is a malformed value, with toml++'s reason.
    const bool word = !value.empty() && std::isalpha(static_cast<unsigned char>(value[0])) &&
                      std::all_of(value.begin(), value.end(), [](unsigned char c) {
                        return std::isalnum(c) || c == '_' || c == '-' || c == '.';
                      });
    if (!word)
      fail("the value '" + cut(value) + "' is not a TOML value (" + cut(e.description()) + ")");
    table->insert_or_assign(key, value);
  }
  origins.record(tname, key, change);
}

void apply_unset(toml::table& root, const std::string& path, const std::vector<std::string>& sets,
                 Origins& origins) {
  const std::string change = "--unset " + cut(path);
  auto fail = [&](const std::string& why) { throw SceneError(change + ": " + why); };
  const auto dot = path.find('.');
  const std::string tname = path.substr(0, dot);
  const std::string key = dot == std::string::npos ? "" : path.substr(dot + 1);
  if (tname.empty() || path.find('=') != std::string::npos ||
      (dot != std::string::npos && (key.empty() || key.find('.') != std::string::npos)))
    fail("expected table.key or table, e.g. floor.cor or force");
  for (const auto& set : sets)
    if (set.substr(0, set.find('=')) == path) fail("--set " + cut(set) + " sets it too; give one");

  const auto names = [](const toml::table& table) {
    std::vector<std::string_view> out;
    for (auto&& [name, node] : table) out.push_back(name.str());
    return out;
  };
  // A second --unset of the same key or table has nothing left to remove, and need not.
  const bool removed =
      origins.of(tname, key) == change || origins.of(tname) == "--unset " + cut(tname);
  if (key.empty()) {
    if (!root.erase(tname)) {
      if (removed) return;
      fail("there is no [" + show_key(tname) + "] in " + origins.file() +
           did_you_mean(tname, names(root)));
    }
  } else if (toml::table* table = root[tname].as_table(); !table || !table->erase(key)) {
    if (removed) return;
    fail(table ? "there is no " + show_key(tname) + "." + show_key(key) + " in " + origins.file() +
                     did_you_mean(key, names(*table), tname + ".")
               : "there is no [" + show_key(tname) + "] in " + origins.file() +
                     did_you_mean(tname, names(root)));
  }
  origins.record(tname, key, change);
}

}  // namespace impact
