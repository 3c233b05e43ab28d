// The exact, event-driven solution of (2-1)-(2-4) for a constant or harmonic body force
// f(t) = f + A sin(omega t + phase), advanced forward in time: free flight in closed form
// (HarmonicFlight), each impact found by the certified search of flight_search.hpp (it never
// misses one, grazing ones included) and refined by GSL's Brent solver, Newton's impact law
// v+ = -e v- (e = COR, or 1 without one), and at rest on the floor N = -f(t) >= 0 (2-2) while
// f(t) <= 0: the particle sticks there and lifts off where f crosses 0 upward (in closed form).
//
// Chatter. With e < 1 and a downward force, impacts can accumulate at a finite time (Zeno), as
// for a constant f. The track cuts the sequence off at an impact whose speed V is below
// kChatterCutoff times the largest impact speed seen, when it can certify the rest: with
// g(t) = -f(t), g_k = g(t_k) and |g'| <= C = |A| omega, take the window W0 = 4 e V / (g_k (1 - e)),
// g_min = g_k - C W0, g_max = g_k + C W0 and rho = e sqrt(g_max / g_min). If g_min > 0, rho < 1 and
//   W = 2 e V / (g_min (1 - rho)) <= W0,
// then every later flight of the exact solution lasts at most 2 w / g_min for its launch speed w,
// each impact speed is at most rho times the one before (the work of f over one flight changes
// v^2/2 by at most (g_max - g_min) times its height w^2 / (2 g_min)), so all further impacts lie in
// [t_k, t_k + W] and the particle rests from then on. The track makes the impact at t_k plastic and
// sticks there: its state differs from the exact one only inside that window, by at most
// (e V)^2 / (2 g_min) in u and rho V in v, and the accumulation time lies within W after the stick
// event (chatter_window() gives W). For a constant force rho = e and W = 2 e V / (g (1 - e)), the
// Zeno time t_inf of exact.hpp. Without such a certificate the impacts are followed one by one.
//
// Time is absolute here (the force depends on it); at(t) and advance() must be called with
// non-decreasing t. Events go to the sink in increasing t as the track passes them.
#pragma once

#include <optional>

#include "impact/events.hpp"
#include "impact/flight_search.hpp"
#include "impact/model.hpp"

namespace impact {

// The relative impact speed below which a chatter is cut off (see above).
inline constexpr double kChatterCutoff = 1e-8;

class EventTrack {
 public:
  // From (t0, initial). Throws std::invalid_argument for an expression force (its reference is the
  // method event_driven), non-finite data, u0 < phi or a COR outside [0, 1].
  EventTrack(const Model& model, const State& initial, double t0);

  void set_event_sink(EventSink sink) { sink_ = std::move(sink); }

  // The state at t >= every earlier t (v right-continuous), adding to `impulse` the contact
  // impulse delivered since the previous call: the impact jumps plus -f over the time at rest.
  // An impact at t0 on the floor (u0 = phi, v0 < 0) counts in the first call with t > t0.
  State advance(double t, double& impulse);

  // The flight that holds the state at t, when no event lies between the last call and t: a
  // sample is then flight->at(t, sin, cos) of its theta(t), as the caller can compute it. nullptr
  // otherwise (call advance()).
  const HarmonicFlight* free_flight_until(double t) const {
    return resting_ || t > certified_ || (contact_ && t >= contact_->t) ? nullptr : &flight_;
  }

  // False once a contact search stalled or exceeded its step budget (the state is then unreliable).
  bool converged() const { return converged_; }
  // W of the last chatter cut-off (see above), 0 when there was none.
  double chatter_window() const { return chatter_window_; }
  double phi() const { return model_.phi; }
  // The time of the first impact passed so far.
  std::optional<double> first_impact() const { return first_impact_; }

 private:
  void start_flight(double t, double v, bool at_crossing = false);
  void impact(const Contact& c, double& impulse);
  void settle(double t);
  bool chatter_certified(double t, double V);
  void emit(double t, EventKind kind, double v_before, double v_after) const;

  Model model_;
  ForceBounds bounds_;
  double e_;
  EventSink sink_;
  HarmonicFlight flight_;
  double certified_ = 0;  // no contact of the current flight in [start, certified_)
  std::optional<Contact> contact_;
  std::optional<double> first_impact_;
  bool resting_ = false;
  double rest_start_ = 0, lift_ = 0, t_now_ = 0;
  double max_speed_ = 0, chatter_window_ = 0;
  bool converged_ = true;
};

}  // namespace impact
