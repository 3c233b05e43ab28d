// Work against precision on the impact oscillator: every method that takes a force of the state
// (the capability state_force of capabilities.hpp: direct and moreau_jean over the step h,
// event_driven over its tolerance) on the force expression "-u - cos(omega*t)", its sup error in u
// against the exact-flight reference (oscillator_law.hpp) at the grid times and the CPU time of its
// solve (time_solve of work_precision.hpp). The others (exact, fb_newton, penalty, direct_located)
// refuse the scene and are left out. A chaotic scene is run over a horizon shorter than its
// Lyapunov time (estimate_lyapunov on two nearby runs of the scene's reference).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/fit.hpp"
#include "analysis/impact_oscillator/oscillator_theory.hpp"
#include "analysis/work_precision.hpp"
#include "impact/run/scene.hpp"

namespace impact::impact_oscillator {

struct OscillatorPoint {
  double h = 0;          // the grid step
  double tolerance = 0;  // event_driven's rtol = atol; 0 for a time-stepper
  double sup_u = 0;      // max_l |u^l - u(t_l)|
  double sup_v = 0;      // max_l |v^l - v(t_l)|
  SolveCost cost;
};

struct OscillatorCurve {
  std::string method;
  bool step_sweep = true;
  std::vector<OscillatorPoint> points;
  OrderFit order;  // of sup_u against h (a step sweep)
};

// The methods with and without the capability state_force.
std::vector<std::string_view> state_force_methods();
std::vector<std::string_view> refusing_methods();

// The scene of an experiment file as an oscillator: its floor, COR, omega (read back from the
// expression) and initial state; throws std::runtime_error when the scene is not
// "-u - cos(omega*t)" with a COR.
Oscillator oscillator_of(const Scene& scene);

// Errors of one run of `method` with parameters `params` on the scene's grid h against the
// reference.
OscillatorPoint measure(const Scene& scene, const MethodParams& params, double h,
                        const std::optional<TimingRule>& rule);

// Every curve of the scene: the time-steppers over `steps`, event_driven over `tolerances` on the
// grid `tolerance_grid`.
std::vector<OscillatorCurve> oscillator_curves(const Scene& scene, const std::vector<double>& steps,
                                               const std::vector<double>& tolerances,
                                               double tolerance_grid,
                                               const std::optional<TimingRule>& rule);

// method,h,tolerance,sup_u,sup_v,cpu_min,cpu_median rows.
std::string curve_rows(const std::string& scene, const std::vector<OscillatorCurve>& curves);

}  // namespace impact::impact_oscillator
