// A scene as a TOML document built in memory (the Python module builds one from a dict), for
// load_run() (read_scene.hpp): the same checks and messages as a file, without a TOML text in
// between. Not installed: it includes toml++, which the installed headers do not.
#pragma once

#include <toml++/toml.h>

#include <string>

namespace impact {

struct SceneDocument {
  toml::table root;
  std::string source = "<document>";  // what messages call it
};

}  // namespace impact
