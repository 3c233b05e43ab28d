// The exact solution for a linear force of the state plus a harmonic term,
//   f(t, u, v) = f - k (u - u_eq) - c v + a sin(omega t + phase)   (Model::linear),
// advanced forward in time: the event logic of exact_march.hpp (Newton's law, chatter cut off under
// a certified window, rest while the floor holds the particle, lift-off) with the closed-form
// flights of linear_flight.hpp and their certified contact search, impact times refined by Brent
// to a few ulps. The method exact follows such a force with it; the other methods take the force
// as the expression of the state it is (force.hpp, linear_as_expression) and are checked against
// it.
//
// On the floor the state is (phi, 0), so the force there is a constant plus the harmonic term,
// f_rest(t) = f - k (phi - u_eq) + a sin(omega t + phase): lift-off, the impulse of a rest and
// the sticking test are those of the harmonic force (flight_search.hpp) with f_rest. A chatter is
// cut off under the window of exact_march.hpp with the push's range over the bounce box
// u in [phi, phi + V^2/(2 g_min)], |v| <= V: g_min = -f_rest - |a| omega W0 - |c| V - |k| h_max,
// g_max = -f_rest + |a| omega W0 + |c| V + |k| h_max.
#pragma once

#include <optional>
#include <string>

#include "impact/model/model.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/references/flight_search.hpp"
#include "impact/references/linear_flight.hpp"

namespace impact {

// The LinearForce of linear_flight.hpp that a model with a linear part states.
LinearForce linear_force(const Model& model);

// The Law of ExactMarch for a linear force (exact_march.hpp names the interface).
class LinearLaw {
 public:
  LinearLaw(const LinearForce& force, double phi);

  void start(double t, double gap, double v, bool at_crossing);
  std::optional<Contact> search(double horizon, long& budget) {
    return search_linear_contact(flight_, gap_, certified_, checked_, horizon, budget);
  }
  State at(double t) const {
    const FlightMotion m = flight_.relative(t);
    return {gap_ + m.u, m.v};
  }
  double certified() const { return certified_; }
  void give_up_until(double t) { certified_ = t; }
  double force_bound() const { return flight_.acceleration_bound(certified_).B; }
  std::string failure() const { return {}; }

  double force(double t) const { return rest_law_.force(t); }
  double rate(double t) const { return rest_law_.rate(t); }
  Lift lift_after(double t) const { return rest_law_.lift_after(t); }
  double rest_impulse(double a, double b) const { return rest_law_.rest_impulse(a, b); }
  std::optional<double> chatter_window(double t, double V, double e) const;

  const LinearFlight& flight() const { return flight_; }

 private:
  LinearForce force_;
  double phi_;
  ClosedFormLaw rest_law_;  // the force on the floor, f_rest(t)
  LinearFlight flight_;
  double gap_ = 0;  // at the flight's start
  double certified_ = 0, checked_ = 0;
};

using LinearTrack = ExactMarch<LinearLaw>;

// The exact solution of a model with a linear part from (t0, initial). Throws
// std::invalid_argument where ExactMarch does, for non-finite force data, a harmonic part
// without omega > 0, an expression beside the linear part or internal variables.
LinearTrack linear_track(const Model& model, const State& initial, double t0);

}  // namespace impact
