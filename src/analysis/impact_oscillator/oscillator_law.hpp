// The impact oscillator's exact-flight reference: the core's exact solution for a linear force
// (linear_law.hpp: the event logic of ExactMarch with the closed-form flights of
// linear_flight.hpp and their certified contact search), started on the oscillator, and the impact
// map between two impacts. The package's own methods take this force as an expression f(t, u, v)
// (event_driven integrates it with rk8pd); this reference is what they are checked against.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "analysis/impact_oscillator/oscillator_theory.hpp"
#include "impact/model/event.hpp"
#include "impact/references/flight_search.hpp"
#include "impact/references/linear_flight.hpp"
#include "impact/references/linear_law.hpp"

namespace impact::impact_oscillator {

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
