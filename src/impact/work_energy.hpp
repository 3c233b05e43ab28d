// The energy the E channel reports. For a constant force it is (3-1), E = v^2/2 - f u, conserved
// in free flight and by an elastic impact (Lemma 1). With a time-dependent force f(t), v^2/2 - f u
// is not conserved between impacts; what is, and what an elastic impact keeps, is
//   E(t) = v^2/2 - f(0) u(0) - W(t),   W(t) = the work of f along the trajectory, int_0^t f du,
// (d/dt (v^2/2) = (N + f) v, and N v = 0 except at impacts, where an elastic one keeps |v| and u).
// For a constant f, W(t) = f (u(t) - u(0)) and E is (3-1); it is then computed as (3-1), so that
// it is bit for bit the same.
#pragma once

#include <cstdint>

#include "impact/force.hpp"
#include "impact/model.hpp"

namespace impact {

// E(t) along a run sampled on the grid t_l = l h, fed every step in order. The work of step l is
// the step's mean force times the step's displacement, (u^{l+1} - u^l) (1/h) int f over
// [t_l, t_{l+1}] (ForceFunction::step_mean, the discrete force of the schemes): the work of f
// along the straight line between the samples. Its error on a step is int (f - mean f)(u' - mean
// u'), at most h^3 sup|f'| sup|u''| on a step of free flight and h^2 sup|f'| |jump of v| on a step
// with an impact: second order in h over a run with finitely many impacts, and exact for a
// constant force. A force of the state f(t, u, v) (force.hpp) is taken at the step's start state,
// (1/h) int f(t, u^l, v^l) dt over the step, the discrete force of the schemes (scheme_flight.hpp):
// the work int f v dt along the path to first order in h only, since f changes with the state
// over the step by O(h); E then drifts by O(h) over a run, for every method.
class WorkEnergy {
 public:
  WorkEnergy(const Model& model, const State& initial, double h);

  // The state at t_l, for l = 1, 2, ... in order (l = 0 is the initial state).
  void step(std::int64_t l, const State& s);
  // E at the state last given (the initial one before any step).
  double energy(const State& s) const;
  // W(t_l) for the last l given.
  double work() const { return work_; }

 private:
  ForceFunction force_;
  double h_;
  bool constant_;
  double start_;  // f(0) u(0)
  double work_ = 0.0;
  State last_;  // the state at the last step
};

// E at t = 0, v0^2/2 - f(0) u0 (f(0) at the initial state): what the scene reader checks to be
// finite.
double initial_energy(const Model& model, const State& initial);

}  // namespace impact
