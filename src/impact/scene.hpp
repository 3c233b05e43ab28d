// A scene: the TOML file that states one run (initial data, floor, force, time grid, method,
// output). It states only what it needs; what it leaves out is absent, not zero.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

#include "impact/model.hpp"

namespace impact {

// Bad input: the message names the file, the key, the value and what is allowed.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

enum class Channel { u, v, N, E, iterations };
std::string_view channel_name(Channel c);

struct OutputSpec {
  std::vector<Channel> channels{Channel::u, Channel::v};
  std::int64_t every = 1;  // write every k-th step; t = 0 and the last step always
};

struct Scene {
  std::string source;        // where the scene came from, for messages
  State initial;
  Model model;
  double T = 0.0;
  Grid grid;                 // steps = T/h rounded (within 1e-9 relative), else ceil(T/h)
  std::string method;
  toml::table method_params; // the [method] table, read by the chosen solver (see MethodParams)
  OutputSpec output;

  // The scene as TOML, with overrides applied: what a run actually used.
  toml::table document;
};

// Reads and validates a scene file; `overrides` are "table.key=value" strings (the value is read
// as a TOML value, or as a string when it is a bare word) applied before validation.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});
// The same from text in memory; `source` names it in messages.
Scene parse_scene(std::string_view text, const std::string& source,
                  const std::vector<std::string>& overrides = {});

// Typed, range-checked access to the solver's keys in [method]; remembers which keys a solver read
// so that a key no solver reads (a typo) is rejected with the list of allowed keys.
class MethodParams {
 public:
  explicit MethodParams(const Scene& scene) : scene_(scene) {}
  // A number in [lo, hi] (open at lo when lo_open), defaulting to `fallback` when absent.
  double number(std::string_view key, double fallback, double lo, double hi, bool lo_open = false);
  std::int64_t integer(std::string_view key, std::int64_t fallback, std::int64_t lo,
                       std::int64_t hi);
  std::string choice(std::string_view key, std::string_view fallback,
                     const std::vector<std::string_view>& allowed);
  // Throws SceneError naming any key of [method] that was not read.
  void reject_unread() const;

 private:
  const toml::node* find(std::string_view key);
  const Scene& scene_;
  std::vector<std::string> read_{"name"};
};

}  // namespace impact
