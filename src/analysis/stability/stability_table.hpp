// The tables of the extreme-case map (results/stability/table.md): one letter per run, and per
// case and method what its 10 runs did.
#pragma once

#include <string>

#include "analysis/stability/stability_cases.hpp"

namespace impact::stability {

std::string stability_table(const CaseMap& map);

}  // namespace impact::stability
