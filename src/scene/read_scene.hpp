// The scene reader: a scene file (TOML) and --set overrides into a validated Scene
// (impact/run/scene.hpp). A scene states only what it needs; what it leaves out is absent, not
// zero. Installed with the package as <impact/scene/read_scene.hpp> (the impact::scene target): it
// and the headers it includes from this directory, by quoted same-directory includes that resolve
// both here and there, include no toml++.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "impact/run/any_stepper.hpp"
#include "impact/run/scene.hpp"
#include "scene_error.hpp"

namespace impact {

// What --set and --unset do to a scene before it is validated: `set` holds "table.key=value"
// strings (the value read as a TOML value, or as a string when it is a bare word), `unset`
// "table.key" or "table" strings (each must be in the scene); the unsets are applied first.
struct SceneEdits {
  std::vector<std::string> set, unset;
};
// A scene file (a pipe such as /dev/stdin too), named by its path in messages.
struct SceneFile {
  std::filesystem::path path;
};
// A scene's TOML text in memory, which must outlive the call; `source` names it in messages.
struct SceneText {
  std::string_view text;
  std::string source = "<string>";
};

// The validated Scene of a file or of a text with its edits; a file and its text give the same
// Scene. Throws SceneError naming the source, the key, the value and what is allowed.
Scene read_scene(const SceneFile& file, const SceneEdits& edits = {});
Scene read_scene(const SceneText& text, const SceneEdits& edits = {});

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
Run load_run(const SceneText& text, const std::vector<std::string>& overrides = {},
             const std::vector<std::string>& unsets = {});
// The same for a TOML document in memory (scene_document.hpp, which is not installed: it includes
// toml++); Run::text is empty, as there is no text.
struct SceneDocument;
Run load_run(const SceneDocument& document, const SceneEdits& edits = {});

}  // namespace impact
