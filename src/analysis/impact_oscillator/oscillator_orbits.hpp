// The period-one orbit of the impact oscillator against runs: the acceptance run (settling from
// u0 = 1, v0 = 0), the branch in sigma and in omega (each point started near the closed-form orbit
// and run until the perturbation has decayed below rounding), and the thresholds the runs show:
// period doubling by bisection on the sign of the growth rate of |V_(k+1) - V_k| along runs of the
// impact map, the saddle-node by extrapolating the runs' leading multiplier to 1.
#pragma once

#include <optional>
#include <vector>

#include "analysis/impact_oscillator/oscillator_law.hpp"
#include "analysis/impact_oscillator/oscillator_theory.hpp"

namespace impact::impact_oscillator {

// The last impact of a run against the closed-form orbit.
struct OrbitCheck {
  Oscillator o;
  PeriodOneOrbit orbit;
  double multiplier = 0;                // the leading multiplier's modulus, (O-3)
  int impacts = 0;                      // of the run
  double V = 0, phase = 0;              // of its last impact
  double V_error = 0, phase_error = 0;  // run - formula (the phase on the circle)
};

// Which run: the exact-flight reference (oscillator_law.hpp) or the method event_driven on the
// expression form.
enum class Runner { reference, event_driven };

// From `initial` at t = 0 over [0, T]; the orbit must exist.
OrbitCheck check_run(const Oscillator& o, const State& initial, double T, Runner runner);

// The state at t = 0 of the (1, 1) orbit (a point of the flight between its impacts at t0 - T and
// t0), with v moved by `kick` times V.
State orbit_state_at_zero(const Oscillator& o, const PeriodOneOrbit& orbit, double kick = 0.0);

// The branch: each point from orbit_state_at_zero(kick = 1e-3), run until 1e-3 |lambda|^k is
// below 1e-13 (100 to 4000 impacts).
OrbitCheck check_branch_point(const Oscillator& o, Runner runner);
// The number of impacts check_branch_point runs at a multiplier of this modulus.
int branch_impacts(double multiplier);

// The largest |V_error| and |phase_error| over checks.
struct BranchAgreement {
  double V = 0, phase = 0;
  int points = 0;
};
BranchAgreement agreement(const std::vector<OrbitCheck>& checks);

// The growth rate per impact of |V_(k+1) - V_k| along N impacts of the map from the orbit moved by
// eps in t and V, fitted over k = K..N (the differences evolve by the Jacobian: the slope is
// log |lambda_1| without knowing the fixed point); exp of it is the leading multiplier.
double growth_rate(const Oscillator& o, int N, int K, double eps);

// sigma (omega fixed) or omega (sigma fixed) where the growth rate changes sign, bisected in
// [lo, hi] to `tolerance` (the runs' period doubling).
double bisect_period_doubling_sigma(double omega, double r, double lo, double hi, double tolerance);
double bisect_period_doubling_omega(double sigma, double r, double lo, double hi, double tolerance);
// The saddle-node from runs: (1 - lambda_1)^2 ~ (x - x_sn) near it, with lambda_1 from the runs'
// growth rate at x_sn + offsets (offsets on the stable side), fitted linearly and extrapolated to
// 0.
double extrapolate_saddle_node_sigma(double omega, double r, double sigma_near,
                                     const std::vector<double>& offsets);
double extrapolate_saddle_node_omega(double sigma, double r, double omega_near,
                                     const std::vector<double>& offsets);

// The Jacobian of the impact map by central differences of runs of it (step h in t and V).
std::array<std::array<double, 2>, 2> map_jacobian_by_differences(const Oscillator& o,
                                                                 const PeriodOneOrbit& orbit,
                                                                 double h);

}  // namespace impact::impact_oscillator
