#include "scene/internal_keys.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "impact/forces/internal.hpp"
#include "impact/format.hpp"
#include "scene/scene_error.hpp"
#include "scene/toml_text.hpp"
#include "scene/validate.hpp"

namespace impact {
namespace {

// The keys of one [[internal]] table: one place for the reader, --help, --set, --unset, --vary
// and the scene as run (resolved_scene.cpp).
const KeySpec kInternalKeys[] = {
    {.table = "internal",
     .key = "name",
     .type = KeyType::text,
     .required = true,
     .also = "an identifier, not t, u, v, pi or a channel's name",
     .meaning = "the variable's name, as force.expression, the rates and output.channels read it",
     .get_variable = [](const InternalVariable& z) -> KeyValue { return z.name; },
     .set_variable = [](InternalVariable& z,
                        const KeyValue& v) { z.name = std::get<std::string>(v); }},
    {.table = "internal",
     .key = "initial",
     .type = KeyType::number,
     .required = true,
     .meaning = "z(0), the value at t = 0",
     .get_variable = [](const InternalVariable& z) -> KeyValue { return z.initial; },
     .set_variable = [](InternalVariable& z,
                        const KeyValue& v) { z.initial = std::get<double>(v); }},
    {.table = "internal",
     .key = "rate",
     .type = KeyType::text,
     .required = true,
     .meaning = "g in z' = g(t, u, v, z), a muparser expression of t, u, v and the internal "
                "variables by name",
     .get_variable = [](const InternalVariable& z) -> KeyValue { return z.rate.text(); },
     .set_variable = [](InternalVariable& z,
                        const KeyValue& v) { z.rate = std::get<std::string>(v); }},
};

}  // namespace

std::span<const KeySpec> internal_keys() {
  return kInternalKeys;
}

std::optional<InternalKey> internal_key(std::string_view path) {
  constexpr std::string_view kPrefix = "internal.";
  if (!path.starts_with(kPrefix)) return std::nullopt;
  path.remove_prefix(kPrefix.size());
  const std::size_t dot = path.find('.');
  InternalKey key{std::string(path.substr(0, dot)), nullptr, ""};
  if (dot != std::string_view::npos) key.key = std::string(path.substr(dot + 1));
  for (const KeySpec& spec : kInternalKeys)
    if (spec.key == key.key) key.spec = &spec;
  return key;
}

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
  std::vector<std::string_view> allowed;
  for (const KeySpec& spec : kInternalKeys) allowed.push_back(spec.key);
  for (std::size_t i = 0; i < entries->size(); ++i) {
    std::string entry = where + " #" + std::to_string(i + 1);
    const toml::table* table = entries->get(i)->as_table();
    if (!table) r.fail_table("internal", entry, "must be a table with name, initial and rate");
    for (auto&& [key, value] : *table)
      if (key.str() != "name" && key.str() != "initial" && key.str() != "rate")
        r.fail_table("internal", entry,
                     "unknown key " + std::string(key.str()) + " (allowed: " + join(allowed) + ")");
    const auto* name = table->get_as<std::string>("name");
    if (name) entry += " (" + name->get() + ")";
    // A message about a key names the --set that gave it (internal.NAME.key), else the file.
    const auto fail = [&](const KeySpec& spec, const std::string& what) {
      const std::string& origin =
          name ? r.origins().of("internal", name->get() + "." + std::string(spec.key))
               : r.origins().of("internal");
      throw SceneError(origin + ": " + entry + ": " + what);
    };
    InternalVariable variable;
    for (const KeySpec& spec : kInternalKeys) {
      const toml::node* value = table->get(spec.key);
      const std::string needs = "needs " + std::string(spec.key) + ", " +
                                (spec.type == KeyType::number ? "a finite number" : "a string") +
                                ": " + std::string(spec.meaning);
      if (!value) fail(spec, needs);
      KeyValue read;
      if (spec.type == KeyType::number) {
        // As every number key of a scene reads it (key_reader.cpp): an integer is taken as the
        // double nearest it.
        if (const auto* integer = value->as_integer())
          read = static_cast<double>(integer->get());
        else if (const auto* floating = value->as_floating_point())
          read = floating->get();
        else
          fail(spec, std::string(spec.key) + " = " + show(*value) + ": " + needs);
        if (const auto wrong = check_value(spec, std::get<double>(read)))
          fail(spec, std::string(spec.key) + " = " + show(*value) + ": " + *wrong + " (" +
                         std::string(spec.meaning) + ")");
      } else if (const auto* text = value->as_string()) {
        read = text->get();
      } else {
        fail(spec, std::string(spec.key) + " = " + show(*value) + ": " + needs);
      }
      spec.set_variable(variable, read);
    }
    scene.model.internal.push_back(variable);
    // Written by default, after u and v (output.channels chooses otherwise).
    scene.output.channels.push_back(internal_channel(i));
  }
  try {
    const InternalRates rates(scene.model);
    // Every rate where the run starts, so that one that is not finite there fails with the scene.
    std::array<double, kMaxInternal> rate{};
    const StateWithInternal start = with_internal(scene.model, scene.initial);
    try {
      rates.evaluate(0.0, start, rate);
    } catch (const std::runtime_error& e) {
      throw std::invalid_argument(std::string(e.what()) +
                                  " (the initial state: " + describe(start) + ")");
    }
    scene.model.internal = rates.model().internal;  // the rates compiled, once
  } catch (const std::invalid_argument& e) {
    r.fail_table("internal", where, e.what());
  }
}

}  // namespace impact
