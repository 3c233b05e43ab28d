// The checks of a scene on its plain values, one definition for the scene reader and the sweep: a
// number key's value against its range, and what no single key can check. Each returns what is
// wrong in the reader's words; the caller says where the value came from (the file, a --set, a
// --vary point).
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "impact/run/scene.hpp"
#include "scene/scene_keys.hpp"

namespace impact {

// 2^53: the largest step count T/h a scene may ask for, for which every l and l*h are exact in
// double precision.
inline constexpr double kMaxGridSteps = 9007199254740992.0;

// What is wrong with table.key; with_value: the message shows the key's value before `what`
// ("time.h = 5: must be <= time.T = 1"), else only the key ("output.channels: E: ...").
struct SceneIssue {
  std::string_view table, key;
  std::string what;
  bool with_value = true;
};

// How a message shows another key's value: the reader as it was typed ("1.0"), the sweep as the
// shortest decimal ("1").
using ShowKey = std::function<std::string(std::string_view table, std::string_view key)>;

// The checks that join keys, in the reader's order: u0 >= phi, h <= T, T/h <= 2^53 steps, and a
// finite initial energy when the channels have E.
std::optional<SceneIssue> cross_check(const Scene& scene, const ShowKey& show);

// A number key's value: finite, in the key's range, and whole for an integer key; the reader's
// words for what is allowed.
std::optional<std::string> check_value(const KeySpec& spec, double x);

}  // namespace impact
