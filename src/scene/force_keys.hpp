// The [force] table of a scene: the body force f(t) of (2-1) as a constant f, plus either a
// harmonic term amplitude sin(omega t + phase) or a muparser expression of t, or of t and the state
// u, v (impact/forces/force.hpp evaluates it). Its keys (force_keys(), declared in scene_keys.hpp)
// join the key table, so that the reader checks them and `impact run --help` prints them; the
// checks that involve several keys, or the method, are here.
#pragma once

#include <toml++/toml.h>

#include "scene/key_reader.hpp"
#include "scene/scene_keys.hpp"

namespace impact {

// What no single [force] key can check, after every table is read: an empty [force], a harmonic
// part without its amplitude or omega, an expression together with the harmonic keys, an
// expression that muparser cannot evaluate at t = 0 (the message gives the position). Whether the
// method takes the force is refusal()'s (capabilities.hpp), asked once the whole scene is read.
// Throws SceneError naming where the key came from, the key, its value and what is allowed.
// Compiles the scene's expression (expression.hpp), once, for the internal variables read before.
void check_force(const KeyReader& r, const toml::table& root, Scene& scene);

}  // namespace impact
