#include "analysis/error_analysis/error_campaign.hpp"

#include <cmath>

namespace impact::error_analysis {

double Check::ratio() const {
  // A bound within rounding, or a lower bound on a rounding-sized error, says nothing.
  if (lower) return bound > allowance && measured > allowance ? bound / measured : std::nan("");
  if (bound == 0) return allowance > 0 ? measured / allowance : std::nan("");
  return bound > allowance ? measured / bound : std::nan("");
}

bool is_conjecture(std::string_view name) {
  return name.starts_with("s3.fb_newton.") || name.starts_with("s3.moreau_jean.");
}

}  // namespace impact::error_analysis
