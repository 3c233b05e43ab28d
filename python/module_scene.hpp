// How the Python module reads its `scene` argument (a path, a TOML text or a dict, which becomes
// a TOML document, not a text) and its keywords (set, method, every) into the scene reader's
// source and --set strings, so that a scene from Python is read and checked exactly as
// `impact run SCENE --set ...` reads it.
#pragma once

#include <pybind11/pybind11.h>

#include <optional>
#include <string>
#include <vector>

#include "scene/read_scene.hpp"
#include "scene/scene_document.hpp"

namespace impact::python {

struct SceneSource {
  std::string path;  // a scene file; empty when the scene is `text` or `document`
  std::string text;  // the TOML text of a string scene
  std::optional<SceneDocument> document;  // a dict scene, as the TOML document it stands for
  std::string name;  // what messages call a scene not in a file: "<string>", "<dict>"
  std::vector<std::string> overrides;
};

// scene: a path (str or os.PathLike), a TOML text (a str with a newline) or a dict of tables;
// set: a dict {"table.key": value} or a list of "table.key=value" strings; method and every, when
// not None, add method.name and output.every after them. Throws pybind11::type_error for an
// argument of the wrong type, SceneError (a ValueError) naming the key path for a dict or list
// that contains itself or nests deeper than a scene does.
SceneSource scene_source(pybind11::handle scene, pybind11::handle set, pybind11::handle method,
                         pybind11::handle every);

// The scene and its stepper, or SceneError as `impact run` reports it; `overrides` in place of
// the source's own (a sweep adds its point's).
Run load(const SceneSource& source);
Run load(const SceneSource& source, const std::vector<std::string>& overrides);
// What messages call the scene: its path, or its name.
const std::string& source_name(const SceneSource& source);

// The text of a --set value: TOML's spelling of a bool or a number (a float in round-trip
// precision; a NumPy scalar as the number it holds) or of a list, a string as it is (the reader
// takes a bare word as a string). Anything else (None, a dict, ...) is a SceneError naming
// `what` (e.g. "set['time.h']").
std::string set_value(pybind11::handle value, const std::string& what);

}  // namespace impact::python
