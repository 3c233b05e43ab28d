#include "scene/resolved_scene.hpp"

#include <variant>

#include "scene/scene_keys.hpp"

namespace impact {
namespace {

// The value of a key whose spec has no accessor because the reader requires it (it has no
// default to show in --help).
KeyValue required_value(const Scene& s, const KeySpec& spec) {
  const std::string name = std::string(spec.table) + "." + std::string(spec.key);
  if (name == "initial.u0") return s.initial.u;
  if (name == "initial.v0") return s.initial.v;
  if (name == "time.T") return s.T;
  if (name == "time.h") return s.grid.h;
  if (name == "method.name") return std::string(method_name(s.method));
  return {};
}

}  // namespace

std::string resolved_scene(const Scene& scene) {
  std::string text;
  std::string_view table;
  const auto add = [&](const KeySpec& spec) {
    KeyValue value = spec.get ? spec.get(scene) : required_value(scene, spec);
    // An expression is the whole force: the reader refuses f beside it.
    if (spec.table == "force" && spec.key == "f" && !scene.model.expression.empty()) return;
    if (std::holds_alternative<std::monostate>(value)) return;
    if (spec.table != table) {
      text += (text.empty() ? "[" : "\n[") + std::string(spec.table) + "]\n";
      table = spec.table;
    }
    text += std::string(spec.key) + " = " + show_value(value) + "\n";
  };
  for (const KeySpec& spec : scene_keys()) {
    add(spec);
    // The method's own keys follow its name.
    if (spec.table == "method" && spec.key == "name")
      for (const KeySpec& key : method_keys())
        if (key.params == scene.method.index()) add(key);
  }
  // The internal variables, one [[internal]] table each, in the model's order.
  for (const InternalVariable& variable : scene.model.internal) {
    text += "\n[[internal]]\n";
    for (const KeySpec& spec : internal_keys())
      text += std::string(spec.key) + " = " + show_value(spec.get_variable(variable)) + "\n";
  }
  return text;
}

}  // namespace impact
