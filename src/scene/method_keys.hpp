// The [method] table of a scene, read into the method's plain parameter struct (registry.hpp):
// every method's keys, defaults and ranges are here, and only here.
#pragma once

#include <toml++/toml.h>

#include <string>

#include "impact/registry.hpp"
#include "scene/overrides.hpp"

namespace impact {

// Reads the keys of `method` (name included) for the method `info`; throws SceneError naming
// where the key came from (`origins`), the key, the value and the allowed range, or the allowed
// keys for a key the method does not read (a typo).
MethodParams read_method_keys(const toml::table& method, const Origins& origins,
                              const MethodInfo& info);

}  // namespace impact
