// Every key a scene may have: its table, type, range and meaning. The reader checks values against
// these tables and `impact run --help` prints them, so the two cannot disagree. Defaults are not
// written here: they are those of the plain structs (impact/run/scene.hpp, each method's Params),
// read through each key's accessor.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "impact/methods/capabilities.hpp"
#include "impact/run/scene.hpp"

namespace impact {

struct Capabilities;  // impact/methods/capabilities.hpp

enum class KeyType { number, integer, name, names, text };

// The values a number or integer key accepts; the whole real line means any finite number.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false;

  bool bounded() const {
    return lo > -std::numeric_limits<double>::infinity() &&
           hi < std::numeric_limits<double>::infinity();
  }
  bool contains(double x) const { return (lo_open ? x > lo : x >= lo) && x <= hi; }
  // "> 0", ">= 1", "in (0, 1]"; empty for the whole line.
  std::string text() const;
};

// A key's value as the reader hands it to the scene: a number, an integer, a name, a list of
// names, or nothing (a key without a default).
using KeyValue =
    std::variant<std::monostate, double, std::int64_t, std::string, std::vector<std::string>>;

// KeySpec::params of a key that every scene reads.
inline constexpr std::size_t kEveryScene = std::variant_npos;

struct KeySpec {
  std::string_view table, key;
  // [method] keys: the method that reads it, as its index in MethodParams (method_index<P>, so
  // that no name is spelt twice); kEveryScene: a key of every scene.
  std::size_t params = kEveryScene;
  KeyType type = KeyType::number;
  Range range = {};                                          // number, integer
  std::span<const std::string_view> (*choices)() = nullptr;  // name, names
  bool required = false;
  std::string_view also = {};  // what the reader checks beyond the range, for --help
  // A use of the key that only some methods honour, for --help: what it is, and the capability
  // (capabilities.hpp) whose methods --help lists.
  std::string_view only_some = {};
  bool Capabilities::*only_with = nullptr;
  std::string_view meaning = {};
  KeyValue (*get)(const Scene&) = nullptr;  // its default (nullptr: required, or none)
  void (*set)(Scene&, const KeyValue&) = nullptr;
  // A key of each [[internal]] table (internal_keys.cpp), which --set, --unset and --vary address
  // as internal.NAME.key: its value in one variable.
  KeyValue (*get_variable)(const InternalVariable&) = nullptr;
  void (*set_variable)(InternalVariable&, const KeyValue&) = nullptr;

  // The name of the method that reads the key; empty for a key of every scene.
  std::string_view method() const {
    return params == kEveryScene ? std::string_view() : methods()[params].name;
  }
};

struct TableSpec {
  std::string_view name;
  bool required;
};

// The tables of a scene, in the order they are read.
std::span<const TableSpec> scene_tables();
// The keys of every scene, table by table (method.name included).
std::span<const KeySpec> scene_keys();
// The keys of [method] that each method reads (method_keys.cpp).
std::span<const KeySpec> method_keys();
// The keys of [force] (force_keys.cpp), which scene_keys() includes.
std::span<const KeySpec> force_keys();
// The keys of [bonding] (bonding_keys.cpp), which scene_keys() includes.
std::span<const KeySpec> bonding_keys();
// The keys of each [[internal]] table (internal_keys.cpp): name, initial, rate (table "internal").
std::span<const KeySpec> internal_keys();
// The internal variable's key a --set, --unset or --vary names as internal.NAME.key: the variable's
// index in the model and the key's spec; SceneError-free (nullopt) when `path` is not of that form.
struct InternalKey {
  std::string name;     // NAME
  const KeySpec* spec;  // nullptr: no such key of [[internal]]
  std::string key;      // as written
};
std::optional<InternalKey> internal_key(std::string_view path);

// The key table.key of every scene (nullptr if there is none).
const KeySpec* find_scene_key(std::string_view table, std::string_view key);
// The names of table's keys ("name" and the method's keys for [method], given a method).
std::vector<std::string_view> key_names(std::string_view table, std::string_view method = {});
// A value for a message or --help: 0.5, 1e-15, 50, 'rk8pd', ['u', 'v'], none.
std::string show_value(const KeyValue& value);

}  // namespace impact
