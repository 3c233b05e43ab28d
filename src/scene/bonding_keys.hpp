// The [bonding] table of a scene: the bonding field of impact/model/bonding.hpp, adhesion with
// damage. Its keys (bonding_keys(), declared in scene_keys.hpp) join the key table, so that the
// reader checks their ranges and `impact run --help` prints them; what joins them to the rest of
// the scene is checked here.
#pragma once

#include <toml++/toml.h>

#include "scene/key_reader.hpp"
#include "scene/scene_keys.hpp"

namespace impact {

// After every table is read: a bonding field that acts (gamma beta0^2 != 0) is refused beside
// [[internal]] (the state's z holds beta and D, model.hpp), with a force other than a constant f
// (its E would need the work of f(t) beside the bonds' energy, not built), and by exact where its
// closed form does not hold (no_damage_well_refusal, exact_bonded.hpp); a method without the
// bonding capability is refusal()'s (capabilities.hpp), asked once the scene is read. Otherwise the
// channels beta and D join the default output. Throws SceneError naming where the key came from,
// the key, its value and what is allowed.
void check_bonding(const KeyReader& r, const toml::table& root, Scene& scene);

}  // namespace impact
