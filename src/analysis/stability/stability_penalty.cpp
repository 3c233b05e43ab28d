#include "analysis/stability/stability_penalty.hpp"

#include <numbers>

#include "impact/loop/simulate.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/steppers/penalty.hpp"

namespace impact::stability {

Scene penalty_scene(const std::string& stepper, double c_N, const State& initial, double T,
                    double h) {
  PenaltyParams params;
  params.stiffness = c_N;
  params.stepper = stepper;
  return make_scene(Model{0, kGravity, {}}, initial, T, h, params);
}

ContactResolution resolve_contact(const std::string& stepper, double c_N) {
  ContactResolution c;
  const double V = std::sqrt(2 * -kGravity * 1.0), w = std::sqrt(c_N), g_eq = kGravity / c_N;
  const double alpha = std::atan2(V / w, -g_eq);
  c.duration_exact = 2 * (std::numbers::pi - alpha) / w;
  c.penetration_exact = -g_eq + std::sqrt(g_eq * g_eq + V * V / c_N);
  c.h = c.duration_exact / 200;
  const Scene scene = penalty_scene(stepper, c_N, State{0, -V}, 1.5 * c.duration_exact, c.h);
  try {
    AnyStepper solver = make_stepper(scene);
    double min_gap = 0, impulse = 0, exit_time = NAN;
    State before = scene.initial;
    simulate(solver, scene.initial, scene.grid,
             [&](std::int64_t l, const State& s, const StepInfo& info) {
               if (l == 0) return;
               min_gap = std::fmin(min_gap, s.u);
               if (std::isnan(exit_time)) {
                 impulse += c.h * info.contact_force;
                 // Leaving the floor between t_{l-1} and t_l: interpolate the crossing.
                 if (before.u < 0 && s.u >= 0)
                   exit_time = scene.grid.t(l - 1) + c.h * -before.u / (s.u - before.u);
               }
               before = s;
             });
    c.penetration = -min_gap;
    c.duration = exit_time;
    c.impulse = impulse;
  } catch (const NumericalError& e) {
    c.outcome = e.converged ? Outcome::non_finite : Outcome::failure;
  }
  return c;
}

StiffRun run_stiff(const Scene& scene, std::int64_t max_work) {
  const double c_N = std::get<PenaltyParams>(scene.method).stiffness, f = scene.model.f;
  const auto spring_energy = [&](const State& s) {
    const double pen = std::fmax(-s.u, 0.0);
    return 0.5 * s.v * s.v - f * s.u + 0.5 * c_N * pen * pen;
  };
  const double E0 = spring_energy(scene.initial);
  double drift = 0;
  StiffRun r;
  r.run = run_stability_check(scene, {max_work, [&](std::int64_t, const State& s, const StepInfo&) {
                                        drift = std::fmax(drift, std::fabs(spring_energy(s) - E0));
                                      }});
  const Outcome o = r.run.check.outcome;
  if (o == Outcome::ok || o == Outcome::inaccurate) r.energy_drift = drift;
  return r;
}

}  // namespace impact::stability
