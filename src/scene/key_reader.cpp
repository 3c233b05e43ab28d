#include "scene/key_reader.hpp"

#include <cmath>

#include "scene/scene_error.hpp"
#include "scene/suggest.hpp"
#include "scene/toml_text.hpp"
#include "scene/validate.hpp"

namespace impact {
namespace {

// table.key as a message names it; a table inside another (force.linear) by its dotted path.
std::string key_name(std::string_view table, std::string_view key) {
  std::string name;
  for (std::size_t dot; (dot = table.find('.')) != std::string_view::npos;) {
    name += show_key(table.substr(0, dot)) + ".";
    table.remove_prefix(dot + 1);
  }
  return name + show_key(table) + "." + show_key(key);
}

std::vector<std::string_view> choices(const KeySpec& spec) {
  const auto names = spec.choices();
  return {names.begin(), names.end()};
}

// Where a key of another table, or of another method, belongs: "; did you mean floor.phi?" or
// "; theta is a key of moreau_jean".
std::string elsewhere(std::string_view table, std::string_view key) {
  const auto same = [&](std::string_view name) { return edit_distance(name, key) == 0; };
  for (const KeySpec& spec : scene_keys())
    if (spec.table != table && same(spec.key))
      return "; did you mean " + std::string(spec.table) + "." + std::string(spec.key) + "?";
  std::vector<std::string_view> methods;
  for (const KeySpec& spec : method_keys())
    if (spec.table == table && same(spec.key)) methods.push_back(spec.method());
  if (methods.empty()) return "";
  return "; " + show_key(key) + " is a key of " + join(methods);
}

}  // namespace

void KeyReader::fail(std::string_view table, std::string_view key, const std::string& what) const {
  throw SceneError(origins_.of(table, key) + ": " + key_name(table, key) + ": " + what);
}

void KeyReader::fail_value(std::string_view table, std::string_view key, const toml::node& node,
                           const std::string& allowed) const {
  throw SceneError(origins_.of(table, key) + ": " + key_name(table, key) + " = " + show(node) +
                   ": " + allowed);
}

void KeyReader::fail_table(std::string_view table, const std::string& name,
                           const std::string& what) const {
  throw SceneError(origins_.of(table) + ": " + name + ": " + what);
}

void KeyReader::only(const toml::table& table, std::string_view where,
                     const std::vector<std::string_view>& allowed,
                     const std::string& unknown) const {
  for (auto&& [key, node] : table) {
    bool known = false;
    for (auto a : allowed) known = known || a == key.str();
    if (known) continue;
    if (where.empty())
      fail_table(
          key.str(), show_key(key.str()),
          "unknown table (allowed: " + join(allowed) + ")" + did_you_mean(key.str(), allowed));
    // A key of another table first: phi in [time] is floor.phi, not a typo of h.
    std::string hint = elsewhere(where, key.str());
    if (hint.empty()) hint = did_you_mean(key.str(), allowed, std::string(where) + ".");
    // A key also shows its value, which helps to spot what the typo meant.
    fail_value(where, key.str(), node,
               (unknown.empty()
                    ? "unknown key (allowed in [" + std::string(where) + "]: " + join(allowed) + ")"
                    : unknown + " (allowed: " + join(allowed) + ")") +
                   hint);
  }
}

const toml::table* KeyReader::table(std::string_view name, bool required) const {
  // A table inside another (force.linear) by its path; the outer one is read first.
  const toml::node* node =
      name.find('.') == std::string_view::npos ? root_.get(name) : root_.at_path(name).node();
  if (!node) {
    if (required) fail_table(name, "[" + std::string(name) + "]", "required table is missing");
    return nullptr;
  }
  if (!node->is_table()) {
    // force.linear = 3: a key of the outer table, where a --set of it is recorded.
    if (const auto dot = name.rfind('.'); dot != std::string_view::npos)
      fail_value(name.substr(0, dot), name.substr(dot + 1), *node, "must be a table");
    fail_table(name, std::string(name) + " = " + show(*node), "must be a table");
  }
  return node->as_table();
}

KeyValue KeyReader::value(const KeySpec& spec, const toml::node& node) const {
  switch (spec.type) {
    case KeyType::number: {
      double x = 0.0;
      if (const auto* i = node.as_integer())
        x = static_cast<double>(i->get());
      else if (const auto* f = node.as_floating_point())
        x = f->get();
      else
        fail_value(spec.table, spec.key, node, "must be a number");
      if (const auto wrong = check_value(spec, x)) fail_value(spec.table, spec.key, node, *wrong);
      return x;
    }
    case KeyType::integer: {
      const auto* i = node.as_integer();
      if (!i) fail_value(spec.table, spec.key, node, "must be an integer " + spec.range.text());
      if (const auto wrong = check_value(spec, static_cast<double>(i->get())))
        fail_value(spec.table, spec.key, node, *wrong);
      return i->get();
    }
    case KeyType::name: {
      const auto* s = node.as_string();
      if (!s)
        fail_value(spec.table, spec.key, node, "must be a string, one of " + join(choices(spec)));
      for (auto c : spec.choices())
        if (c == s->get()) return s->get();
      fail_value(spec.table, spec.key, node,
                 "must be one of " + join(choices(spec)) + did_you_mean(s->get(), choices(spec)));
    }
    case KeyType::text:
      if (const auto* s = node.as_string()) return s->get();
      fail_value(spec.table, spec.key, node, "must be a string");
    case KeyType::names:
      break;  // read by its own table's reader (output.channels depends on the method)
  }
  fail_value(spec.table, spec.key, node, "cannot be read here");
}

void KeyReader::read(const toml::table& table, const KeySpec& spec, Scene& scene) const {
  if (const toml::node* node = table.get(spec.key))
    spec.set(scene, value(spec, *node));
  else if (spec.required)
    fail(spec.table, spec.key, "required key is missing");
}

}  // namespace impact
