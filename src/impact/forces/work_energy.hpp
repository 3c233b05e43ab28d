// The energy the E channel reports. For a constant force it is (3-1), E = v^2/2 - f u, conserved
// in free flight and by an elastic impact (Lemma 1). With a time-dependent force f(t), v^2/2 - f u
// is not conserved between impacts; what is, and what an elastic impact keeps, is
//   E(t) = v^2/2 - f(0) u(0) - W(t),   W(t) = the work of f along the trajectory, int_0^t f du,
// (d/dt (v^2/2) = (N + f) v, and N v = 0 except at impacts, where an elastic one keeps |v| and u).
// For a constant f, W(t) = f (u(t) - u(0)) and E is (3-1); it is then computed as (3-1), so that
// it is bit for bit the same.
//
// A bonding field that acts (bonding.hpp) adds its energy gamma beta^2 Phi(g) to E, and W stays the
// work of f alone (the pull is not in W):
//   E(t) = v^2/2 - f(0) u(0) - W(t) + gamma beta^2 Phi(g),
// whose rate in flight is 2 gamma beta beta' Phi(g) = -D' (paper_notes/bonding_field.md, "With a
// force of time"), so E + D = E(0) in flight. The state's z gives beta and D (model.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "impact/forces/force.hpp"
#include "impact/model/event.hpp"
#include "impact/model/model.hpp"

namespace impact {

// E(t) along a run sampled on the grid t_l = l h, fed every step in order. W is the work of the
// force the method applied, whatever it reads (t, u, v, the internal variables z):
//  - for a time-stepper, the work of step l is the step's mean force times the step's
//    displacement, (u^{l+1} - u^l) (1/h) int f over [t_l, t_{l+1}] (ForceFunction::step_mean, the
//    discrete force of the schemes), a force of the state and of z taken at the step's start state
//    (u^l, v^l, z^l), as the schemes take it (scheme_flight.hpp, with_internal.hpp). For direct
//    and moreau_jean (theta = 1/2), whose free flight is v^{l+1} = v^l + h f^l, u^{l+1} = u^l +
//    h (v^l + v^{l+1})/2, this is exactly the work of the force they applied, so E is conserved in
//    their free flight to rounding; for a method whose flight is not that parabola (penalty's ODE),
//    its error on a step is int (f - mean f)(u' - mean u'), at most h^3 sup|f'| sup|u''| in free
//    flight and h^2 sup|f'| |jump of v| on a step with an impact: second order over a run with
//    finitely many impacts; for a force of the state, first order (f changes with the state over
//    the step by O(h));
//  - for a method that follows the motion itself between its events (exact, event_driven:
//    follows_motion), u'' = f in flight, so the work of f over a flight is its change of v^2/2 (to
//    the accuracy of the solution: rounding for exact's closed forms, rk8pd's tolerance for
//    event_driven), and nothing at rest (u = phi stays). W(t) is then v(t)^2/2 - v0^2/2 minus what
//    the impacts up to t changed v^2/2 by (event()), and E is E(0) plus those changes: constant in
//    flight, lowered by each impact by what it takes. With the bonds, u'' = f - gamma beta^2 R(g)
//    in flight, and the pull's work along the motion is the change of gamma beta^2 Phi(g) plus D
//    (d/dt gamma beta^2 Phi = gamma beta^2 R v - D'), so W(t) is that plus the above, and E is
//    E(0) plus the impacts' changes minus D(t), D the one the method integrated.
class WorkEnergy {
 public:
  WorkEnergy(const Model& model, const State& initial, double h, bool follows_motion = false);

  // The state at t_l, for l = 1, 2, ... in order (l = 0 is the initial state); with the internal
  // variables z^l, which the force of the next step reads.
  void step(std::int64_t l, const StateWithInternal& s);
  void step(std::int64_t l, const State& s) { step(l, StateWithInternal{s, z0_}); }
  // An event of a method that follows the motion, in increasing t, before the steps after it.
  void event(const Event& e);
  // E at the state s with its internal variables (beta and D for a bonded model): s is the state
  // last given (the initial one before any step).
  double energy(const StateWithInternal& s) const;
  // The same with the internal variables of the state last given.
  double energy(const State& s) const { return energy(StateWithInternal{s, last_.z}); }
  bool follows_motion() const { return follows_motion_; }

 private:
  ForceFunction force_;
  double h_;
  bool constant_, follows_motion_;
  double start_;            // f(0) u(0)
  double initial_kinetic_;  // v0^2/2
  double work_ = 0.0;
  double impacts_ = 0.0;          // the changes of v^2/2 at the impacts so far (follows_motion)
  std::optional<Bonding> bonds_;  // a bonding field that acts (bonded(), model.hpp), or none
  double phi_;
  double initial_bonds_;  // gamma beta0^2 Phi(g(0)), 0 without bonds
  std::array<double, kMaxInternal> z0_;
  StateWithInternal last_;  // the state at the last step
};

// E at t = 0, v0^2/2 - f(0) u0 (f(0) at the initial state): what the scene reader checks to be
// finite.
double initial_energy(const Model& model, const State& initial);

}  // namespace impact
