// The [method] table of a scene, read into the method's plain parameter struct (method_params.hpp):
// every method's keys, ranges and meanings are here, and only here (their defaults are the
// Params structs'); `impact run --help` prints the same table.
#pragma once

#include <toml++/toml.h>

#include "impact/run/scene.hpp"
#include "scene/key_reader.hpp"

namespace impact {

// Reads the keys of `method` for the method scene.method already names (its defaults); throws
// SceneError naming where the key came from, the key, the value and the allowed range, or the
// allowed keys for a key the method does not read (a typo).
void read_method_keys(const KeyReader& r, const toml::table& method, Scene& scene);

}  // namespace impact
