// The exact-flight reference of the impact oscillator: the event logic of the package's exact
// solution (EventTrackOf, event_track.hpp: Newton's law, chatter cut off under a certified window,
// rest while the floor holds the particle, lift-off) with the closed-form flights of a linear
// force (linear_flight.hpp) and their certified contact search, impact times refined by Brent to a
// few ulps. The package's own methods take this force as an expression f(t, u, v) (event_driven
// integrates it with rk8pd); this law is the closed-form reference they are checked against.
//
// On the floor the state is (phi, 0), so the force there is a constant plus the harmonic term,
// f_rest(t) = f0 - k (phi - u_eq) + a sin(omega t + phase): lift-off, the impulse of a rest and
// the sticking test are those of the harmonic force (flight_search.hpp) with f_rest. A chatter is
// cut off under the window of event_track.hpp with the push's range over the bounce box
// u in [phi, phi + V^2/(2 g_min)], |v| <= V: g_min = -f_rest - |a| omega W0 - |c| V - |k| h_max,
// g_max = -f_rest + |a| omega W0 + |c| V + |k| h_max.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/impact_oscillator/oscillator_theory.hpp"
#include "impact/event_track.hpp"
#include "impact/events.hpp"
#include "impact/flight_search.hpp"
#include "impact/linear_flight.hpp"

namespace impact::impact_oscillator {

// The Law of EventTrackOf for a linear force (event_track.hpp names the interface).
class LinearLaw {
 public:
  LinearLaw(const LinearForce& force, double phi);

  void start(double t, double gap, double v, bool at_crossing);
  std::optional<Contact> search(double horizon, long& budget) {
    return search_linear_contact(flight_, gap_, certified_, checked_, horizon, budget);
  }
  State at(double t) const {
    const Motion m = flight_.relative(t);
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

using LinearTrack = EventTrackOf<LinearLaw>;

// The oscillator's exact-flight track from (t0, initial).
LinearTrack oscillator_track(const Oscillator& o, const State& initial, double t0 = 0.0);

// The events of the track over [t0, T] (at most max_events; the run stops there), and whether it
// converged.
struct TrackRun {
  std::vector<Event> events;
  bool converged = true;
  State final_state{};
};
TrackRun run_track(const Oscillator& o, const State& initial, double T, double t0 = 0.0,
                   std::size_t max_events = 1u << 20);

// One step of the impact map (t_i, V_i) -> (t_(i+1), V_(i+1)): the flight leaves the wall at t_i
// with speed r V_i; t_(i+1) is the contact itself (Contact::t - late), V_(i+1) its speed. nullopt
// when no contact comes within `horizon` of t_i.
struct Impact {
  double t = 0, V = 0;
};
std::optional<Impact> impact_map(const Oscillator& o, const Impact& from, double horizon = 100);

// Whether the orbit's flight from one impact reaches the wall first after T (and not before).
bool orbit_is_admissible(const Oscillator& o, const PeriodOneOrbit& orbit);

// The events of the method event_driven on the expression form "-u - cos(omega t)" over [0, T] on
// the grid h (its samples do not move its events), with its default tolerances.
std::vector<Event> event_driven_events(const Oscillator& o, const State& initial, double T,
                                       double h);

// Impact phase t mod 2 pi/omega in [0, 2 pi/omega).
double impact_phase(double t, double omega);

}  // namespace impact::impact_oscillator
