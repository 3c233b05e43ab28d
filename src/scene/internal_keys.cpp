#include "scene/internal_keys.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "impact/internal.hpp"
#include "scene/toml_text.hpp"

namespace impact {

void read_internal(const KeyReader& r, const toml::table& root, Scene& scene) {
  const toml::node* node = root.get("internal");
  if (!node) return;
  const toml::array* entries = node->as_array();
  const std::string where = "[[internal]]";
  if (!entries || entries->empty())
    r.fail_table("internal", where,
                 "must be an array of tables, each with name, initial and rate (write "
                 "[[internal]], not [internal])");
  if (entries->size() > kMaxInternal)
    r.fail_table("internal", where,
                 std::to_string(entries->size()) + " internal variables; at most " +
                     std::to_string(kMaxInternal) + " are allowed");
  for (std::size_t i = 0; i < entries->size(); ++i) {
    const std::string entry = where + " #" + std::to_string(i + 1);
    const toml::table* table = entries->get(i)->as_table();
    if (!table) r.fail_table("internal", entry, "must be a table with name, initial and rate");
    for (auto&& [key, value] : *table)
      if (key.str() != "name" && key.str() != "initial" && key.str() != "rate")
        r.fail_table("internal", entry,
                     "unknown key " + std::string(key.str()) + " (allowed: name, initial, rate)");
    InternalVariable variable;
    const auto* name = table->get_as<std::string>("name");
    const auto* rate = table->get_as<std::string>("rate");
    const toml::node* initial = table->get("initial");
    if (!name) r.fail_table("internal", entry, "needs name, a string (the variable's name)");
    if (!rate)
      r.fail_table("internal", entry,
                   "needs rate, a string: g in z' = g(t, u, v, z), a muparser expression");
    if (!initial || !initial->is_number())
      r.fail_table("internal", entry, "needs initial, a finite number (z at t = 0)");
    variable.name = name->get();
    variable.rate = rate->get();
    variable.initial = initial->value<double>().value_or(NAN);
    if (!std::isfinite(variable.initial))
      r.fail_table("internal", entry,
                   "initial = " + show(*initial) + ": must be a finite number (z at t = 0)");
    scene.model.internal.push_back(variable);
    // Written by default, after u and v (output.channels chooses otherwise).
    scene.output.channels.push_back(internal_channel(i));
  }
  try {
    const InternalRates parses(scene.model);
  } catch (const std::invalid_argument& e) {
    r.fail_table("internal", where, e.what());
  }
  const MethodInfo& method = method_info(scene.method);
  if (!method.can.internal_variables)
    r.fail_value("method", "name", *root.get("method")->as_table()->get("name"),
                 "'" + std::string(method.name) +
                     "' does not follow internal variables, and [[internal]] gives " +
                     std::to_string(entries->size()) + ": use " +
                     join(methods_with(&Capabilities::internal_variables)));
}

}  // namespace impact
