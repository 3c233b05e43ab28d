// Grazing and chatter of the impact oscillator against their asymptotic laws
// (oscillator_theory.hpp): Nordmark's square-root law measured where it holds, on the first impact
// of a pass that would reach delta past the wall (not on the period-one orbit, whose speed near
// grazing is linear in delta), and the accumulation time of a chatter, 2 v0/(a (1 - r)) with v0
// the take-off speed, with its first-order correction for a push that changes along the chatter.
#pragma once

#include <limits>
#include <vector>

#include "analysis/fit.hpp"
#include "analysis/impact_oscillator/oscillator_theory.hpp"
#include "impact/model/event.hpp"

namespace impact::impact_oscillator {

struct GrazingPoint {
  double delta = 0;  // how far past the wall the free orbit would go (from the stored floor)
  double V = 0;      // the first impact speed, exact-flight reference
  double exact = 0;  // omega sqrt(delta (2 |gamma| - delta))
  double event_driven = std::numeric_limits<double>::quiet_NaN();  // its first impact speed
  double orbit_V = 0;  // the (1, 1) orbit's speed at sigma = |gamma| - delta (closed form)
};

struct GrazingLaw {
  std::vector<GrazingPoint> points;
  OrderFit reference;                 // ln V against ln delta: order = the exponent
  OrderFit event_driven;              // the same from event_driven's runs (when run)
  OrderFit orbit;                     // the (1, 1) orbit's V against delta: exponent 1
  double sqrt_2a = 0;                 // the law's prefactor sqrt(2 (1 + |gamma|))
  double max_relative_deviation = 0;  // of V from the exact expression, over the points
};

// delta = 10^(log_min + k/per_decade), k = 0..decades*per_decade; the floor at -|gamma| + delta,
// the start on the free orbit u = |gamma| cos(omega t) at t = 0 (u = |gamma|, v = 0).
GrazingLaw grazing_law(double omega, double r, double log_min, int decades, int per_decade,
                       bool with_event_driven);

// A chatter from the wall at t0 with take-off speed v0: the impacts of the exact-flight map until
// the take-off speed falls below 1e-7 v0, then the geometric tail; against 2 v0/(a0 (1 - r)) and
// its first-order correction, with the push a0 = phi + cos(omega t0), a1 = -omega sin(omega t0).
struct ChatterPoint {
  double t0 = 0, v0 = 0;
  double a0 = 0, a1 = 0;
  double t_inf = 0;                   // the accumulation time
  double prediction = 0;              // t0 + 2 v0/(a0 (1 - r))
  double prediction_first_order = 0;  // with the first-order factor
  int impacts = 0;
  double relative_deviation() const { return (t_inf - prediction) / (prediction - t0); }
  double relative_deviation_first_order() const {
    return (t_inf - prediction_first_order) / (prediction - t0);
  }
};
ChatterPoint chatter_accumulation(const Oscillator& o, double t0, double v0);

// A run from the wall (u = phi, v = v0 at t = 0) through its chatter, rest and lift-off: the
// events of the reference and of event_driven, the accumulation time of the reference's map and
// where the particle lifts, acos(-phi)/omega + 2 pi m/omega (the first after the rest).
struct StickingRun {
  std::vector<Event> reference, event_driven;
  double t_inf = 0;
  double lift_off = 0;
};
StickingRun sticking_run(const Oscillator& o, double v0, double T);

}  // namespace impact::impact_oscillator
