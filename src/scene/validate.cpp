#include "scene/validate.hpp"

#include <algorithm>
#include <cmath>

#include "impact/forces/force.hpp"
#include "impact/forces/work_energy.hpp"
#include "impact/format.hpp"

namespace impact {

std::optional<SceneIssue> cross_check(const Scene& scene, const ShowKey& show) {
  const double u0 = scene.initial.u, phi = scene.model.phi, T = scene.T, h = scene.grid.h;
  if (u0 < phi)
    return SceneIssue{
        "initial", "u0",
        "must be >= floor.phi = " + shortest(phi) + " (the particle starts above the floor)"};
  if (h > T) return SceneIssue{"time", "h", "must be <= time.T = " + show("time", "T")};
  if (!(T / h <= kMaxGridSteps))
    return SceneIssue{"time", "h",
                      "T/h = " + shortest(T / h) +
                          " steps is too many to count exactly (at most 2^53 = 9007199254740992)"};
  const auto& channels = scene.output.channels;
  if (std::find(channels.begin(), channels.end(), Channel::E) != channels.end() &&
      !std::isfinite(initial_energy(scene.model, scene.initial)))
    return SceneIssue{"output", "channels",
                      "E: the initial energy v0^2/2 - f(0) u0 (3-1) is beyond the double range "
                      "(v0 = " +
                          shortest(scene.initial.v) + ", f(0) = " +
                          shortest(ForceFunction(scene.model).at(0.0, scene.initial)) +
                          ", u0 = " + shortest(scene.initial.u) + ")",
                      false};
  return std::nullopt;
}

std::optional<std::string> check_value(const KeySpec& spec, double x) {
  if (spec.type == KeyType::integer) {
    if (!(x == std::floor(x)) || !spec.range.contains(x))
      return "must be an integer " + spec.range.text();
    return std::nullopt;
  }
  if (!std::isfinite(x)) {  // nan and inf are TOML numbers, but not a scene's
    std::string allowed = "must be a finite number";
    if (const std::string range = spec.range.text(); !range.empty()) allowed.append(" ") += range;
    return allowed;
  }
  if (!spec.range.contains(x)) return "must be " + spec.range.text();
  return std::nullopt;
}

}  // namespace impact
