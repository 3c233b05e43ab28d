// The step sizes of a convergence study (Section 4 and Lemma 4): log-spaced sweeps, steps that
// put an impact on the grid, and steps that put it a fixed fraction of a step after a grid point.
#pragma once

#include <cstdint>
#include <vector>

namespace impact {

// `count` log-spaced step sizes from h_max down to h_min (log_spaced of fit.hpp).
struct StepSweep {
  double h_max = 2e-2, h_min = 1e-6;
  int count = 20;
  std::vector<double> steps() const;
};

// The step t_impact / m nearest each h (m a whole number): the impact at t_impact is the grid
// point t_m.
std::vector<double> aligned_steps(const std::vector<double>& h, double t_impact);

// The h >= floor of a list, in its order.
std::vector<double> at_least(std::vector<double> h, double floor);

// The step h = t_impact / (m + theta): the grid point t_m lies a fraction theta of a step before
// the impact at t_impact (for f = 0 the particle is then theta h |v| above the floor at t_m).
inline double step_with_fraction(double t_impact, std::int64_t m, double theta) {
  return t_impact / (static_cast<double>(m) + theta);
}

}  // namespace impact
