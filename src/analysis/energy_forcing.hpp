// The energy statements of the paper with a time-dependent body force f(t): the energy (3-1)/(4-5)
// E = v^2/2 - f u is defined for a constant f only. With f(t) two energies are candidates:
//   E^l = (v^l)^2/2 - f(t_l) u^l, the printed formula with the force of the moment, and
//   W^l = (v^l)^2/2 - f(0) u^0 - sum_{k<l} f^k (u^{k+1} - u^k), the kinetic energy minus the work
//         of the step-mean force f^k (ForceFunction::step_mean) done so far, started at E^0; its
//         continuous counterpart is v^2/2 - f(0) u(0) - int_0^t f v, and for a constant f, W = E.
//         It is the E channel of a run with f(t) (WorkEnergy, impact/forces/work_energy.hpp).
// (4-1)-(4-3) give W^{l+1} - W^l = N^l (u^{l+1} - u^l) = -N^l (u^l - phi) <= 0: the argument of
// (4-6) carries over to W, not to E (E^{l+1} - E^l = W^{l+1} - W^l - (f(t_{l+1}) - f^l) u^{l+1}
// + (f(t_l) - f^l) u^l, of either sign).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "impact/forces/force.hpp"
#include "impact/forces/scheme_flight.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/model/model.hpp"

namespace impact {

// The step-by-step energy checks of one run.
struct ForcedEnergyCounts {
  std::int64_t steps = 0;
  std::int64_t work_rises = 0;              // steps with W^{l+1} - W^l beyond round-off
  double max_work_rise_over_tolerance = 0;  // max_l (W^{l+1} - W^l) / round-off, 0 if W never rises
  std::int64_t energy_rises = 0;            // steps with E^{l+1} - E^l beyond round-off
  double max_energy_rise = 0;               // max_l (E^{l+1} - E^l), J/kg
};

// Collects the increments of one run step by step (observe), and counts them against the
// round-off tolerance of bounds.hpp once the run's maxima are known (finish): energy_evaluation_
// roundoff with |f| = sup|f|, plus rebound_energy_roundoff on a contact step (tolerances.hpp), plus
// for a harmonic force the error of the schemes' grid phasor (phasor_energy_roundoff).
class ForcedEnergyMonitor {
 public:
  ForcedEnergyMonitor(const Model& model, double h, const State& initial);
  // The step from t_{l-1} to t_l, l >= 1, that produced s with contact force N^{l-1}.
  void observe(std::int64_t l, const State& s, double contact_force);
  ForcedEnergyCounts finish(double sup_force, double T, double max_u, double max_v) const;

 private:
  struct Increment {
    double work, energy, rebound_roundoff;
  };
  ForceFunction force_;
  double h_, phi_;
  State previous_;
  std::vector<Increment> increments_;
};

// The schemes' free flight evaluates its harmonic terms (scheme_flight.hpp) to within (a/omega) d
// in v and (a/omega)(T + 2/omega) d in u, d = SchemeFlight::kHarmonicTermError, and a step passes
// that to one increment: (v^2/2) changes by up to 2 max|v| (a/omega) d, f^l (u^{l+1} - u^l) by up
// to 2 sup|f| (a/omega)(T + 2/omega) d. 0 without a harmonic part.
double phasor_energy_roundoff(const Model& model, double sup_force, double T, double max_v);

struct ForcedEnergySummary {
  std::int64_t steps = 0, work_rises = 0, energy_rises = 0;
  int energy_rise_runs = 0;  // runs in which E rises beyond round-off at some step
  int runs = 0;
  double max_work_rise_over_tolerance = 0, max_energy_rise = 0;
};
void accumulate(ForcedEnergySummary& summary, const ForcedEnergyCounts& counts);

// Lemma 1 with f(t): s (L E)(s) = E(0) for s > 1 checked, as in lemma1.hpp, on the samples of a run
// over [0, T] (linear interpolation), for E^l, for the printed E with the constant part of f only
// (v^2/2 - f u), and for W^l. The largest |relative deviation| over the s values.
struct Lemma1Forcing {
  double amplitude = 0, omega = 0;
  double energy = 0;                                      // E^l = (v^l)^2/2 - f(t_l) u^l
  double energy_constant = 0;                             // (v^l)^2/2 - f u^l, f the constant part
  double work = 0;                                        // W^l
  double work_final_change = 0, energy_final_change = 0;  // (X^n - X^0) / |X^0|
  double work_max_rise = 0, energy_max_rise = 0;  // max_l (X^{l+1} - X^l) / |X^0|, 0 if none
};
// The case: u0 = 1 m, v0 = 0, phi = 0, f = -9.80665 + amplitude sin(omega t), the method with the
// COR (1: elastic; direct's v^{l+1} = -v^l on a contact step loses no energy wherever the impact
// falls, up to the O(h) work of the step) at h = kLemma1ForcingH.
inline constexpr double kLemma1ForcingH = 1e-3;
Lemma1Forcing lemma1_forcing(double amplitude, double omega, double cor, const MethodParams& method,
                             std::span<const double> s_values, double T);

}  // namespace impact
