#include "analysis/work_precision_lyapunov.hpp"

#include <gsl/gsl_fit.h>

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "analysis/work_precision_reference.hpp"
#include "impact/output/csv.hpp"
#include "impact/run/scene.hpp"

namespace impact {

LyapunovEstimate estimate_lyapunov(Scene scene, double horizon, double h, double delta0,
                                   double saturation) {
  const Grid grid = Grid::covering(horizon, h);
  const ReferenceTrajectory a = reference_trajectory(scene.model, scene.initial, grid);
  State nearby = scene.initial;
  nearby.v += delta0;
  const ReferenceTrajectory b = reference_trajectory(scene.model, nearby, grid);
  LyapunovEstimate e;
  e.delta0 = delta0;
  std::vector<double> fit_t, fit_log;
  double envelope = 0;
  for (std::int64_t l = 0; l <= grid.steps; ++l) {
    const State& x = a.states[static_cast<std::size_t>(l)];
    const State& y = b.states[static_cast<std::size_t>(l)];
    const double d = std::hypot(x.u - y.u, x.v - y.v);
    envelope = std::fmax(envelope, d);
    e.t.push_back(grid.t(l));
    e.distance.push_back(d);
    e.envelope.push_back(envelope);
    if (envelope < saturation) {
      fit_t.push_back(grid.t(l));
      fit_log.push_back(std::log(envelope));
      e.fitted_until = grid.t(l);
    }
  }
  if (fit_t.size() < 2) throw std::runtime_error("estimate_lyapunov: the runs separate at once");
  double intercept = 0, slope = 0, c00 = 0, c01 = 0, c11 = 0, sumsq = 0;
  gsl_fit_linear(fit_t.data(), 1, fit_log.data(), 1, fit_t.size(), &intercept, &slope, &c00, &c01,
                 &c11, &sumsq);
  e.lambda = slope;
  e.lyapunov_time = 1 / slope;
  return e;
}

std::optional<double> parting_time(const LyapunovEstimate& estimate, double gap) {
  for (std::size_t i = 0; i < estimate.t.size(); ++i)
    if (estimate.envelope[i] > gap) return estimate.t[i];
  return std::nullopt;
}

std::string lyapunov_csv(const LyapunovEstimate& estimate) {
  std::string text = "t,distance,envelope\n";
  for (std::size_t i = 0; i < estimate.t.size(); ++i)
    text += round_trip(estimate.t[i]) + "," + round_trip(estimate.distance[i]) + "," +
            round_trip(estimate.envelope[i]) + "\n";
  return text;
}

}  // namespace impact
