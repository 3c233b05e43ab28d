#include "analysis/step_sweep.hpp"

#include <cmath>

#include "analysis/fit.hpp"

namespace impact {

std::vector<double> StepSweep::steps() const {
  return log_spaced(h_max, h_min, count);
}

std::vector<double> aligned_steps(const std::vector<double>& h, double t_impact) {
  std::vector<double> out;
  for (double x : h) out.push_back(t_impact / std::round(t_impact / x));
  return out;
}

std::vector<double> at_least(std::vector<double> h, double floor) {
  std::erase_if(h, [&](double x) { return x < floor; });
  return h;
}

}  // namespace impact
