// The paper's scheme (5-1) with its impact located inside the step: an event-capturing variant of
// `direct` (paper_notes/error_analysis.md, "Beyond order one"). A step whose free flight (5-1)
// with N^l = 0 ends above the floor is direct's step. A step whose free flight ends at or below
// the floor is flown again inside the step, on the step's own model, the parabola
//   g(tau) = g^l + v^l tau + f^l tau^2 / 2,  0 <= tau <= h  (g = u - phi, f^l the step's force),
// whose first root tau_1 is the impact (closed form); Newton's law v+ = -e v- acts there (e = COR,
// or 1 without one, as for moreau_jean and exact) and the rest of the step, h - tau_1, is flown
// from the floor with any further impacts, the accumulation of a Zeno sequence included, in closed
// form (bounce_from_floor). For a constant force the parabola is the exact flight, so the stepper
// reproduces the exact solution at every grid time up to rounding. For f(t) the parabola places
// the impact to O(h^3) and the velocities on both sides of it take the impulse of f over the two
// parts of the step (ForceFunction::integral): with the step's mean force instead, the velocity
// after the impact would be off by (1 + e) D(tau), D(tau) = int_0^tau (f - f^l) ~ f' h^2 / 8,
// which varies with where the impact falls in its step (a second-order error with an erratic
// constant); what is left is the free flight's, second order (error_analysis.md, "Beyond order
// one").
// The step's impulse is whatever the velocity says, h N^l = v^{l+1} - v^l - h f^l, so the impulse
// identity (4-9) with the body force holds to rounding.
#pragma once

#include <cstdint>

#include "impact/forces/force.hpp"
#include "impact/forces/free_flight.hpp"
#include "impact/forces/scheme_flight.hpp"
#include "impact/methods/capabilities.hpp"
#include "impact/methods/method_params.hpp"
#include "impact/model/contact_law.hpp"
#include "impact/model/model.hpp"

namespace impact {

// The first tau >= 0 at which the parabola g + v tau + f tau^2 / 2 (g >= 0) reaches the floor
// moving down or at rest, and the speed there, sqrt(v^2 - 2 f g); `found` is false when it never
// does (v >= 0 and f >= 0, or v < 0 and f > 0 turning back above the floor).
struct FloorArrival {
  bool found = false;
  double tau = 0, speed = 0;
};
FloorArrival floor_arrival(const State& gap_state, double f);

// The state r after leaving the floor upwards with speed w >= 0 under the constant force f, with
// Newton's law of COR e at every return: the bounces of speeds w e^k in closed form (their number
// from the geometric sum of their flight times), and rest (0, 0) from the accumulation point
// t = 2 w / (|f| (1 - e)) on for f < 0 and e < 1 (from the first return for e = 0).
State bounce_from_floor(double w, double r, double f, double e);

// Whether the parabola from (gap, v) under f > 0 goes below the floor inside (0, h) and comes back
// above it by h: a bounce that the grid values alone do not show (for f <= 0 the parabola is
// concave, so it is above the floor between two grid values that are).
inline bool dips_below_floor(const State& s, double h, double f) {
  if (!(f > 0) || !(s.v < 0) || -s.v >= f * h) return false;
  return s.u < s.v * s.v / (2 * f);  // the minimum g - v^2 / (2 f) is below the floor
}

// One step of the located scheme from the state (gap, v) at t_l over h under the force f (the
// step's f^l), whose free flight (5-1) ends at `free`: the state at t_{l+1}. When rounding puts the
// step's parabola above the floor throughout, `free` decides: the particle is there if it is above
// the floor, else the impact is at t_{l+1}.
State located_step(const State& gap_state, const State& free, double h, double f, double e);
// The same for a time-dependent force, from t_l: the velocity just before the impact is
// v^l + int_{t_l}^{t_l + tau} f and the rest of the step is flown under its own mean force.
State located_step(const State& gap_state, const State& free, double t_l, double h, double f,
                   const ForceFunction& force, double e);

class DirectLocated {
 public:
  DirectLocated(const Model& model, double h, const DirectLocatedParams& params)
      : DirectLocated(model, contact_law(model, MethodParams(params)), h, params) {}
  // `law`: contact_law(model, params) (capabilities.hpp), computed once by make_stepper.
  DirectLocated(const Model& model, const ContactLaw& law, double h, const DirectLocatedParams&)
      : phi_(model.phi),
        f_(model.f),
        e_(newton_e(law)),
        h_(h),
        constant_(constant_force(model)),
        flight_(model, h),
        force_(model) {}

  void initialize(const State& s, std::int64_t l) {
    gap_ = {s.u - phi_, s.v};
    start_flight(l);
  }

  StepInfo do_step(State& s, std::int64_t l) {
    StepInfo info;
    // (5-1) with N^l = 0 from the last anchor: for a constant force direct's closed form
    // (free_flight.hpp), else the scheme's flight under f(t) (scheme_flight.hpp).
    State free;
    double f = f_;
    if (constant_) {
      free_flight(anchor_.u, anchor_.v, static_cast<double>(l + 1 - anchor_l_) * h_, f_, free.u,
                  free.v);
    } else {
      free = flight_.step(l);
      f = flight_.step_force();
    }
    if (free.u > 0 && !dips_below_floor(gap_, h_, f)) [[likely]] {
      gap_ = free;
    } else {
      info.contact_force = impact(l, free, f);
    }
    s = {phi_ + gap_.u, gap_.v};
    return info;
  }

 private:
  // The step with an impact: located_step from gap_, and a new free flight from its end; returns
  // N^l. Out of line, so that the free steps' loop keeps its state in registers (direct.hpp).
  [[gnu::noinline]] double impact(std::int64_t l, State free, double f) {
    const State before = gap_;
    gap_ = constant_ ? located_step(before, free, h_, f, e_)
                     : located_step(before, free, static_cast<double>(l) * h_, h_, f, force_, e_);
    const double impulse = gap_.v - before.v - h_ * f;
    start_flight(l + 1);
    return impulse > 0 ? impulse / h_ : 0.0;
  }

  // A free flight starts from gap_ at t_l.
  void start_flight(std::int64_t l) {
    anchor_ = gap_;
    anchor_l_ = l;
    if (!constant_) flight_.start(l, gap_);
  }

  double phi_, f_, e_, h_;
  bool constant_;
  State gap_;                  // (u - phi, v) at t_l
  State anchor_;               // where the free flight started (constant force)
  std::int64_t anchor_l_ = 0;  // and when
  SchemeFlight flight_;        // the free flight under f(t), in gap coordinates
  ForceFunction force_;        // the impulses of f(t) on both sides of an impact
};

}  // namespace impact
