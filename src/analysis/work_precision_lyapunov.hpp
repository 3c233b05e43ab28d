// The largest Lyapunov exponent of a scene, from two nearby runs of its reference (`exact` for a
// harmonic force): the second starts with v0 + delta0. Their distance in the phase plane,
// d(t) = sqrt((u1 - u2)^2 + (v1 - v2)^2) at the grid times, grows as delta0 e^(lambda t) while it
// is small; at an impact it jumps (the two impact at slightly different times), so lambda is the
// least-squares slope of log max_{s <= t} d(s) against t, fitted while that envelope stays below
// `saturation`. The work-precision study measures errors over a horizon shorter than 1 / lambda,
// so that an error made early grows by less than a factor e by the end.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "impact/run/scene.hpp"

namespace impact {

struct LyapunovEstimate {
  double lambda = 0;                          // 1/s
  double lyapunov_time = 0;                   // 1 / lambda, s
  double delta0 = 0;                          // the initial separation in v0
  double fitted_until = 0;                    // the last time of the fit, s
  std::vector<double> t, distance, envelope;  // at the grid times, up to `horizon`
};

// Runs the scene's reference twice over [0, horizon] on the grid of step h.
LyapunovEstimate estimate_lyapunov(Scene scene, double horizon, double h, double delta0 = 1e-10,
                                   double saturation = 1e-3);

// Where the two runs part by more than `gap`: the first grid time at which the envelope exceeds
// it; nullopt when they stay within it up to the horizon. An error below the references' own
// spread measures the reference, not the method.
std::optional<double> parting_time(const LyapunovEstimate& estimate, double gap);

// t, d(t), its running maximum: the CSV the figure reads.
std::string lyapunov_csv(const LyapunovEstimate& estimate);

}  // namespace impact
