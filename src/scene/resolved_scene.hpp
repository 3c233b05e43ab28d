// A scene as it runs: every key of its tables with its value, the defaults filled in, as TOML text
// that the reader reads back to the same Scene bit for bit (numbers in their shortest round-trip
// form). For the provenance of what a run writes (provenance.hpp) and for a program that built a
// scene in code and wants its file.
#pragma once

#include <string>

#include "impact/run/scene.hpp"

namespace impact {

std::string resolved_scene(const Scene& scene);

}  // namespace impact
