// Typed, range-checked reading of a scene's keys against their specs (scene_keys.hpp), with
// messages that name where a key came from (the file or a --set), the key, the value and what is
// allowed.
#pragma once

#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

#include "scene/overrides.hpp"
#include "scene/scene_keys.hpp"

namespace impact {

class KeyReader {
 public:
  KeyReader(const toml::table& root, const Origins& origins) : root_(root), origins_(origins) {}

  // A message about table.key, naming where it came from.
  [[noreturn]] void fail(std::string_view table, std::string_view key,
                         const std::string& what) const;
  [[noreturn]] void fail_value(std::string_view table, std::string_view key, const toml::node& node,
                               const std::string& allowed) const;
  // A message about a table; `name` shows it ("[time]", or "time = 1.0").
  [[noreturn]] void fail_table(std::string_view table, const std::string& name,
                               const std::string& what) const;
  const Origins& origins() const { return origins_; }

  // Every key of `table` (every table, for the root: `where` empty) must be in `allowed` (a
  // typo). `unknown` replaces "unknown key" in the message.
  void only(const toml::table& table, std::string_view where,
            const std::vector<std::string_view>& allowed, const std::string& unknown = {}) const;
  // The table `name` (nullptr when absent and not required).
  const toml::table* table(std::string_view name, bool required) const;

  // The value of `node` if it has the type and range `spec` asks for.
  KeyValue value(const KeySpec& spec, const toml::node& node) const;
  // Sets spec's key in `scene` from `table`, if there; a required key must be.
  void read(const toml::table& table, const KeySpec& spec, Scene& scene) const;

 private:
  const toml::table& root_;
  const Origins& origins_;
};

}  // namespace impact
