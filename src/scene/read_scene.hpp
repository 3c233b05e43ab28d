// The scene reader: a scene file (TOML) and --set overrides into a validated Scene
// (impact/scene.hpp). A scene states only what it needs; what it leaves out is absent, not zero.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "impact/registry.hpp"
#include "impact/scene.hpp"
#include "scene/scene_error.hpp"

namespace impact {

// Reads and validates a scene file; `overrides` are "table.key=value" strings (the value is read
// as a TOML value, or as a string when it is a bare word) and `unsets` "table.key" or "table"
// strings (each must be in the file), applied before validation, unsets first. Throws SceneError.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {},
                 const std::vector<std::string>& unsets = {});
// The same from text in memory; `source` names it in messages.
Scene parse_scene(std::string_view text, const std::string& source,
                  const std::vector<std::string>& overrides = {},
                  const std::vector<std::string>& unsets = {});

// The text of a scene file, read by hand rather than by toml::parse_file, so that a pipe
// (/dev/stdin) works, a directory or a device that never ends (/dev/zero) is rejected, and an
// error says why. Throws SceneError.
std::string read_scene_file(const std::string& path);

// A scene and its solver, built once, and the file's text as it was read.
struct Run {
  Scene scene;
  AnyStepper stepper;
  std::string text;
};
Run load_run(const std::string& path, const std::vector<std::string>& overrides = {},
             const std::vector<std::string>& unsets = {});

}  // namespace impact
