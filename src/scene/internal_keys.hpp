// The [[internal]] tables of a scene: the model's internal variables (impact/model/model.hpp), one
// table each, z' = g(t, u, v, z):
//   [[internal]]
//   name = "D"          # as force.expression, the rates and output.channels read it
//   initial = 0.0       # z(0)
//   rate = "v^2"        # g, a muparser expression of t, u, v and the internal variables
// Read before [force], whose expression may read them.
#pragma once

#include <toml++/toml.h>

#include "impact/run/scene.hpp"
#include "scene/key_reader.hpp"

namespace impact {

// Fills scene.model.internal from root's [[internal]] array, if any. Throws SceneError naming the
// file, the entry, the key, its value and what is allowed: an entry that is not a table, a missing
// or unknown key, a name that is not an identifier or is taken, a value that is not finite, a rate
// that does not parse, or more than kMaxInternal entries. Whether the method follows internal
// variables is refusal()'s (capabilities.hpp), asked once the whole scene is read.
void read_internal(const KeyReader& r, const toml::table& root, Scene& scene);

}  // namespace impact
