// Lemma 3 (Section 4): the a priori bounds on the discrete solution of (4-1)-(4-3), the energy
// inequality E^{l+1} <= E^l (4-6) behind them, and the bound on the total impulse h sum N^l that
// the paper draws from (4-9). Everything here measures a run of a stepper against those statements.
//
// The bounds as printed, with the garbled exponent "e^{l|f|T}" read as e^{|f|T} (the proof's
// (4-8)) and A = 2 E^0 + 2 |f| |u^0| + |f| T:
//   max_l |v^l| <= V = sqrt(A (1 + |f| T e^{|f|T})),
//   max_l |u^l| <= |u^0| + (T/2) V,
//   h sum N^l  <= V - v^0   (after (4-9)).
// The u bound rests on (4-7), |u^l| <= |u^0| + (1/2) int_0^{t_l} |v_h|, whose factor 1/2 is wrong:
// (4-2) gives u^l - u^0 = h sum_{k<l} (v^k + v^{k+1}) / 2, a trapezoid sum of |v| with weight 1,
// so |u^l| <= |u^0| + t_l max|v| and the true bound is |u^0| + T V (f = 0, v^0 > 0 moves the
// particle T |v^0| away from u^0). And (4-9) omits the body force: h sum N^l = v^n - v^0 - f T.
#pragma once

#include <cstdint>
#include <vector>

#include "impact/model/model.hpp"
#include "impact/run/any_stepper.hpp"

namespace impact::lemma3 {

struct Lemma3Bounds {
  double velocity = 0;                // V
  double displacement = 0;            // |u^0| + (T/2) V, as printed
  double displacement_corrected = 0;  // |u^0| + T V
  double impulse = 0;                 // V - v^0, the claim after (4-9)
};

Lemma3Bounds lemma3_bounds(const Model& model, const State& initial, double T);
// The same with |f| read as the number F and E^0 = (v^0)^2/2 - f_energy u^0, for a time-dependent
// force under each reading of |f| (lemma3_forcing.hpp); the form above is F = |f|, f_energy = f.
// A reading may make 2E^0 + 2F|u^0| + FT negative; V is then taken as 0.
Lemma3Bounds lemma3_bounds(double F, double f_energy, const State& initial, double T);

struct Lemma3Measurement {
  double T = 0;                // n h
  double max_v = 0;            // max_l |v^l|
  double max_u = 0;            // max_l |u^l|
  double impulse = 0;          // h sum N^l
  double velocity_change = 0;  // v^n - v^0
  // (4-7) as printed: steps l with |u^l| > |u^0| + (1/2) h sum_{k=1..l} |v^k| (the integral of the
  // piecewise constant v_h), beyond the round-off of u.
  std::int64_t printed_4_7_violations = 0;
  // Energy inequality E^{l+1} <= E^l of the proof (4-6), step by step.
  std::int64_t steps = 0;
  std::int64_t energy_increases = 0;   // steps with E^{l+1} > E^l at all (round-off included)
  std::int64_t energy_violations = 0;  // steps with E^{l+1} - E^l > energy_roundoff(l)
  double max_energy_increase = 0;      // max_l (E^{l+1} - E^l), 0 if E never increases
  double max_energy_increase_over_tolerance = 0;  // max_l (E^{l+1} - E^l) / energy_roundoff(l)
};

// Runs the stepper from `initial` over `grid` (streaming; three numbers per step are kept for the
// checks, whose tolerances need the run's maxima) and measures the quantities above.
//
// Round-off tolerance of the energy check, energy_roundoff(l): energy_evaluation_roundoff at T with
// the run's max|u| and max|v|, plus rebound_energy_roundoff on a contact step (tolerances.hpp).
Lemma3Measurement measure_lemma3(AnyStepper& stepper, const Model& model, const State& initial,
                                 const Grid& grid);

// The sweep of the Lemma 3 experiment: every combination of these, phi = 0, no COR (Lemma 3 is
// about (4-1)-(4-3) itself), the direct scheme (5-1), T = kLemma3SweepT.
inline constexpr double kLemma3SweepT = 2.0;
inline constexpr double kLemma3SweepH[] = {1e-1, 1e-2, 1e-3, 1e-4};
inline constexpr double kLemma3SweepF[] = {-9.80665, -1.0, 0.0, 1.0};
inline constexpr double kLemma3SweepU0[] = {0.0, 1.0, 5.0};
inline constexpr double kLemma3SweepV0[] = {-3.0, -0.5, 2.0};

struct Lemma3Run {
  double h = 0, f = 0, u0 = 0, v0 = 0;
  Lemma3Bounds bounds;
  Lemma3Measurement measured;
};

// All 4 x 4 x 3 x 3 = 144 runs, ordered by f, then u0, then v0, then h.
std::vector<Lemma3Run> lemma3_sweep();

// A bound holds when measured <= bound (1 + kBoundSlack). The slack covers round-off only: the
// largest rounding in a measured maximum is that of a rebound velocity 2 (phi - u^l)/h - v^l, one
// ulp of u^l times 2/h, at most 4e-11 relative in this sweep (|u| <= 11, h >= 1e-4); a real
// violation of the bounds is O(1).
inline constexpr double kBoundSlack = 1e-9;

// A measured / bound ratio. The only bound that can be 0 is the impulse claim V - v^0 (f = 0,
// v^0 > 0: V = v^0); the claim then holds iff nothing was measured, and the ratio is taken as 0.
double bound_ratio(double measured, double bound);

struct RatioStats {
  int violations = 0;  // runs with ratio > 1 + kBoundSlack
  double min = 0, median = 0, max = 0;
};

struct Lemma3Summary {
  int runs = 0;
  RatioStats velocity, displacement, displacement_corrected, impulse;
  // max over the runs of |h sum N^l - (v^n - v^0)| ((4-9) as printed) and of
  // |h sum N^l - (v^n - v^0 - f T)| (with the body force).
  double identity_printed_max_residual = 0, identity_corrected_max_residual = 0;
  int printed_4_7_violation_runs = 0;  // runs with a step that breaks (4-7) as printed
  std::int64_t energy_steps = 0, energy_increases = 0, energy_violations = 0;
  double energy_max_increase_over_tolerance = 0;
};

Lemma3Summary summarize_lemma3(const std::vector<Lemma3Run>& runs);

}  // namespace impact::lemma3
