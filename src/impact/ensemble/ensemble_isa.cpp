// Which of the ensemble's instruction sets this processor supports, and the choice among them
// (ensemble_isa.hpp).
#include "impact/ensemble/ensemble_isa.hpp"

#include <stdexcept>
#include <string>
#include <vector>

namespace impact::ensemble_isa {

bool supported(int level) {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  if (level == kAvx512) return __builtin_cpu_supports("avx512f");
  if (level == kAvx2) return __builtin_cpu_supports("avx2");
#endif
  return level == kBaseline;
}

int best_level() {
  for (int level : {kAvx512, kAvx2})
    if (supported(level)) return level;
  return kBaseline;
}

std::vector<std::string_view> supported_names() {
  std::vector<std::string_view> names;
  for (int level : {kAvx512, kAvx2, kBaseline})
    if (supported(level)) names.push_back(kLevelNames[level]);
  return names;
}

int supported_level(std::string_view name) {
  for (int level : {kAvx512, kAvx2, kBaseline})
    if (kLevelNames[level] == name && supported(level)) return level;
  throw std::invalid_argument("Ensemble: instruction set \"" + std::string(name) +
                              "\" is unknown or not supported by this processor");
}

}  // namespace impact::ensemble_isa
