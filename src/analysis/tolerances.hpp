// Round-off allowances that several analyses share. The energy inequality E^{l+1} <= E^l (4-6) is
// checked step by step on the schemes' runs; E is recomputed from rounded u and v, so it rises by
// round-off at many steps, and a rise counts only beyond the two allowances below (their sum).
#pragma once

#include <cmath>
#include <limits>

namespace impact {

// The round-off of evaluating E = v^2/2 - f u (3-1) on a run that has reached time t with
// max|u| = max_u and max|v| = max_v so far. The free flight from the last contact,
// u_a + t (v_a + t f/2), v_a + t f (free_flight.hpp), has terms up to max|u| + t max|v| + t^2 |f|,
// so E carries an error of a few eps (max|v|^2 + |f| (max|u| + t max|v| + t^2 |f|)); 16 of them are
// allowed.
inline double energy_evaluation_roundoff(double f, double t, double max_u, double max_v) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double F = std::fabs(f);
  return 16 * kEps * (max_v * max_v + F * (max_u + t * max_v + t * t * F));
}

// What a contact step (contact_force > 0) adds to the round-off of E^{l+1} - E^l: the rebound
// velocity 2 (phi - u^l)/h - v^l (5-1) carries the rounding of u^l, one ulp of max(|u^l|, |phi|),
// multiplied by 2/h, which changes v^2/2 by up to 2 |v^{l+1}| ulp / h; twice that is allowed.
// 0 on a step without contact force.
inline double rebound_energy_roundoff(double phi, double h, double u_before, double v_after,
                                      double contact_force) {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double ulp_u = kEps * std::fmax(std::fabs(u_before), std::fabs(phi));
  return contact_force > 0 ? 4 * std::fabs(v_after) * ulp_u / h : 0.0;
}

}  // namespace impact
