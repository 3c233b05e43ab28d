// The instruction sets of the ensemble's vector code (ensemble.cpp): each level is one entry
// point compiled for it, and a processor runs the widest it supports (all give the same bits).
#pragma once

#include <string_view>
#include <vector>

namespace impact::ensemble_isa {

enum Level { kBaseline, kAvx2, kAvx512 };
inline constexpr std::string_view kLevelNames[] = {"baseline", "avx2", "avx512f"};

// Whether this processor runs the level's code.
bool supported(int level);
// The widest level this processor supports.
int best_level();
// The names of the levels this processor supports, widest first.
std::vector<std::string_view> supported_names();
// The level of this name; std::invalid_argument when it is unknown or not supported.
int supported_level(std::string_view name);

}  // namespace impact::ensemble_isa
