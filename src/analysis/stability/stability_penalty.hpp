// Normal compliance (penalty) under gravity, f = -9.80665, phi = 0, as experiments/stability
// drives it towards the Signorini limit: one contact against the closed form of the spring, and a
// run measured by check_stability plus the energy that counts the spring.
#pragma once

#include <cmath>
#include <string>

#include "analysis/stability/stability_runs.hpp"
#include "impact/run/scene.hpp"

namespace impact::stability {

// The penalty scene: phi = 0, gravity, no COR, the stepper and c_N given, GSL's default
// tolerances.
Scene penalty_scene(const std::string& stepper, double c_N, const State& initial, double T,
                    double h);

// The first contact of a particle dropped from u0 = 1 (impact speed V = sqrt(2 |f| 1)),
// integrated on a grid of contact_time / 200: penetration, duration and impulse, with their
// closed forms for the spring u'' = f + c_N (phi - u): about the equilibrium g_eq = f / c_N the
// contact is an oscillation of frequency w = sqrt(c_N) entered at phase alpha = atan2(V / w,
// -g_eq), so it lasts 2 (pi - alpha) / w and reaches g_eq - sqrt(g_eq^2 + V^2 / c_N).
struct ContactResolution {
  double penetration = NAN, duration = NAN, impulse = NAN;  // NaN: the run failed
  double penetration_exact = 0, duration_exact = 0;
  double h = 0;  // the grid step, duration_exact / 200
  Outcome outcome = Outcome::ok;
};
ContactResolution resolve_contact(const std::string& stepper, double c_N);

// A penalty run measured like check_stability (stopped after max_work ODE steps), plus the energy
// that counts the spring, v^2/2 - f (u - phi) + c_N max(phi - u, 0)^2 / 2, which the compliance
// model conserves.
struct StiffRun {
  StabilityRun run;
  double energy_drift = 0;  // max_l |E_spring^l - E_spring^0|, for a run that finished
};
StiffRun run_stiff(const Scene& scene, std::int64_t max_work);

}  // namespace impact::stability
