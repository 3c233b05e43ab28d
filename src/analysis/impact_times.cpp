#include "analysis/impact_times.hpp"

#include <cmath>
#include <cstdint>

namespace impact {

std::vector<double> impact_times(const ExactSolution& x, double T) {
  constexpr std::int64_t kImpactCap = 400;
  const double min_spacing = 1e-9 * std::fmax(1.0, T);
  std::vector<double> times;
  for (std::int64_t k = 1; k <= kImpactCap; ++k) {
    const auto t = x.impact_time(k);
    if (!t || *t > T) break;
    if (times.empty() || *t - times.back() > min_spacing) times.push_back(*t);
  }
  if (const auto rest = x.rest_time(); rest && *rest <= T) times.push_back(*rest);
  return times;
}

}  // namespace impact
