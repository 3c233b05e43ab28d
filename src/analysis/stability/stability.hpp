// Numerical stability of one run (experiments/stability): a run of a scene measured while it
// streams, against the theory and against the exact solution. It reports whether the run finished
// (simulate() stops at the first non-finite value or non-converged solve, so a finished run has
// only finite values), min(u - phi), the steps where the energy (4-5) rose although the theory
// says it cannot, the iterations per step and the error against `exact`, and sums this up in one
// Outcome: the colour of a cell of the stability map.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>

#include "impact/run/scene.hpp"

namespace impact::stability {

enum class Outcome {
  ok,            // finished, within kAccuracy of the exact solution
  inaccurate,    // finished, error beyond kAccuracy
  energy_grows,  // finished, but E^{l+1} > E^l beyond round-off where the theory forbids it
  failure,       // stopped by NumericalError: a solve did not converge (message: step, time, why)
  non_finite,    // stopped by NumericalError: a non-finite value, caught before it was written
  over_budget,   // stopped by StabilityOptions::max_work (too slow, not wrong)
  rejected,      // the method refuses the scene (make_stepper's std::invalid_argument), e.g.
                 // penalty with a COR
};
std::string_view outcome_name(Outcome outcome);

// A run is accurate when max_l |u^l - u(t_l)| <= kAccuracy * (amplitude of the exact motion)
// + kAccuracyFloor * max(1, |phi|) (the floor term for a particle at rest, amplitude 0).
constexpr double kAccuracy = 1e-2;
constexpr double kAccuracyFloor = 1e-12;

struct StabilityOptions {
  // Stop the run once the iterations summed over its steps (ODE steps of penalty, Newton
  // iterations of fb_newton) exceed this; 0 means no limit.
  std::int64_t max_work = 0;
  // Sees every step too, for what the check does not measure (penalty's spring energy).
  std::function<void(std::int64_t l, const State& s, const StepInfo& info)> also;
};

struct StabilityCheck {
  Outcome outcome = Outcome::ok;
  std::string message;     // why the run stopped or was rejected; empty when finished
  std::int64_t steps = 0;  // steps completed
  double min_gap = std::numeric_limits<double>::infinity();  // min_l u^l - phi
  // Whether the theory says E^{l+1} <= E^l for this run: Lemma 3's (4-6) for direct and fb_newton
  // without a COR (fb_newton: E^{l+1} <= E^l + eps/2, since its pair has a N = eps/2 instead of
  // 0), Section 5.2's "energy is lost after the particle's impact" with one, and Newton's impact
  // law with COR <= 1 for exact. moreau_jean and penalty have no such statement (penalty conserves
  // v^2/2 - f u + c_N max(phi - u, 0)^2 / 2, which counts the spring).
  bool energy_bound = false;
  std::int64_t energy_rises = 0;  // steps with E^{l+1} > E^l + round-off (+ eps/2 for fb_newton)
  double max_energy_rise = 0;     // max_l E^{l+1} - E^l, round-off included
  int max_iterations = 0;
  double mean_iterations = 0;
  std::int64_t work = 0;    // iterations summed over the steps
  double error_u = 0;       // max_l |u^l - u(t_l)| against ExactSolution
  double amplitude = 0;     // max_l |u(t_l) - phi|
  double error_energy = 0;  // |E^n - E(t_n)|
};

// Runs the scene's method through simulate() and measures it. Never throws: a failure of the run,
// or a scene its method refuses, is its outcome.
StabilityCheck check_stability(const Scene& scene, const StabilityOptions& options = {});

}  // namespace impact::stability
