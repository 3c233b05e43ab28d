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
// [t_k, t_k + W] and the particle rests after them (while f <= 0, (2-2)). The track makes the
// impact at t_k plastic and sticks there: its state differs from the exact one only inside that
// window, by at most (e V)^2 / (2 g_min) in u and rho V in v, and the accumulation time lies within
// W after the stick event (chatter_window() gives W). For a constant force rho = e and W = 2 e V /
// (g (1 - e)) is t_inf - t_k of exact.hpp. Without such a certificate the impacts are followed one
// by one.
//
// Time is absolute here (the force depends on it); advance() must be called with non-decreasing t.
// Events go to the sink in increasing t as the track passes them.
//
// The same event logic follows an expression force with OdeLaw (ode_flight.hpp, the method
// event_driven): ExactMarch<Law> takes the flights, the lift-off times, the resting impulse and
// the chatter window from its Law and keeps the impacts, sticks and lifts itself.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "impact/model/contact_law.hpp"
#include "impact/model/event.hpp"
#include "impact/model/model.hpp"
#include "impact/references/flight_search.hpp"

namespace impact {

// The relative impact speed below which a chatter is cut off (see above).
inline constexpr double kChatterCutoff = 1e-8;

// Why a track stopped following the solution (converged() false).
struct TrackStop {
  enum class Reason { none, stalled, events, law } reason = Reason::none;
  double t = 0;             // the time the track had reached
  double certified = 0;     // stalled: where the contact search had got to from t
  double force_bound = 0;   // stalled: the bound on |f| the search's steps were certified with
  std::int64_t events = 0;  // the events passed by then,
  double first_event = 0;   // from this time on
};

// The work a run of exact (f(t)) or event_driven may do, as penalty's ODE steps are bounded: the
// events (impacts, sticks and lifts) it passes, method.max_events, and event_driven's ODE steps,
// method.max_ode_steps. `max`, or with 0 the automatic budget, kAutomaticBudget and
// kAutomaticBudgetPerGridStep more per grid step done: a table at 10 Hz passes a few events per
// period and event_driven takes about one ODE step per max_step, while a force that makes the
// particle lift and land every 6e-9 s passed 2.7e7 events in 0.16 s (0.3 us each, 7.4 GB of
// --events by T = 0.25).
inline constexpr std::int64_t kAutomaticBudget = 1'000'000, kAutomaticBudgetPerGridStep = 1000;
inline std::int64_t run_budget(std::int64_t max, std::int64_t grid_steps_done) {
  return max > 0 ? max : kAutomaticBudget + kAutomaticBudgetPerGridStep * grid_steps_done;
}

// The message of a stopped track, what stopped it and what to do, for a stepper's
// failure_reason(): `law_failure` is the law's own account when it gave one, max_events the key's
// value and budget the events the run was allowed.
std::string describe_stop(const TrackStop& stop, std::string_view law_failure,
                          std::int64_t max_events, std::int64_t budget);

template <class Law>
class ExactMarch {
 public:
  // From (t0, initial). Throws std::invalid_argument for non-finite data, u0 < phi or a COR outside
  // [0, 1].
  ExactMarch(Law law, const Model& model, const State& initial, double t0);

  void set_event_sink(EventSink sink) { sink_ = std::move(sink); }

  // The state at t >= every earlier t (v right-continuous), adding to `impulse` the contact
  // impulse delivered since the previous call: the impact jumps plus -f over the time at rest.
  // An impact at t0 on the floor (u0 = phi, v0 < 0) counts in the first call with t > t0.
  State advance(double t, double& impulse);

  // The flight that holds the state at t, when no event lies between the last call and t: a
  // sample is then flight->at(t, sin, cos) of its theta(t), as the caller can compute it. nullptr
  // otherwise (call advance()).
  const HarmonicFlight* free_flight_until(double t) const requires requires(const Law& law) {
    law.flight();
  }
  {
    return resting_ || t > law_.certified() || (contact_ && t >= contact_->t) ? nullptr
                                                                              : &law_.flight();
  }

  // False once a contact search stalled, the law failed or the events passed the limit (the state
  // is then unreliable); stop() says which.
  bool converged() const { return converged_; }
  const TrackStop& stop() const { return stop_; }
  // The events passed so far (impacts, sticks and lifts, emitted or not), and the most the track
  // may pass before it stops.
  std::int64_t events() const { return events_; }
  void set_event_limit(std::int64_t limit) { event_limit_ = limit; }
  Law& law() { return law_; }
  const Law& law() const { return law_; }
  // W of the last chatter cut-off (see above), 0 when there was none.
  double chatter_window() const { return chatter_window_; }
  double phi() const { return phi_; }
  // The time of the first impact passed so far.
  std::optional<double> first_impact() const { return first_impact_; }

 private:
  void start_flight(double t, double v, bool at_crossing = false);
  void launch(double t, double w, double late);
  void impact(const Contact& c, double& impulse);
  void settle(double t);
  void emit(double t, EventKind kind, double v_before, double v_after);
  void stopped(TrackStop::Reason reason);

  Law law_;
  double phi_, e_;
  EventSink sink_;
  std::optional<Contact> contact_;
  std::optional<double> first_impact_;
  bool resting_ = false;
  Lift lift_;
  double rest_start_ = 0, t_now_ = 0;
  double max_speed_ = 0, chatter_window_ = 0;
  bool converged_ = true;
  TrackStop stop_;
  std::int64_t events_ = 0, event_limit_ = std::numeric_limits<std::int64_t>::max();
  double first_event_ = 0;
};

// The exact solution for a constant or harmonic force. Throws std::invalid_argument for an
// expression force (its reference is the method event_driven).
class ClosedFormMarch : public ExactMarch<ClosedFormLaw> {
 public:
  ClosedFormMarch(const Model& model, const State& initial, double t0);
};

template <class Law>
ExactMarch<Law>::ExactMarch(Law law, const Model& model, const State& initial, double t0)
    : law_(std::move(law)),
      phi_(model.phi),
      e_(newton_e(contact_law(model, kElasticReading))),
      t_now_(t0) {
  if (!std::isfinite(model.phi) || !std::isfinite(model.f) || !std::isfinite(initial.u) ||
      !std::isfinite(initial.v) || !std::isfinite(t0))
    throw std::invalid_argument("exact: phi, f, u0, v0 and t0 must be finite");
  if (!(e_ >= 0.0 && e_ <= 1.0)) throw std::invalid_argument("exact: COR must be in [0, 1]");
  if (initial.u < model.phi) throw std::invalid_argument("exact: u0 must be >= phi, (2-2)");
  law_.start(t0, initial.u - model.phi, initial.v, false);
}

template <class Law>
void ExactMarch<Law>::emit(double t, EventKind kind, double v_before, double v_after) {
  if (events_++ == 0) first_event_ = t;
  if (!sink_) return;
  Event event{t, kind, v_before, v_after};
  // A law that follows internal variables gives their values at the event (ode_flight.hpp).
  if constexpr (requires(const Law& law) { law.internal_at(t); })
    event.internal = law_.internal_at(t);
  sink_(event);
}

template <class Law>
void ExactMarch<Law>::stopped(TrackStop::Reason reason) {
  converged_ = false;
  if (stop_.reason == TrackStop::Reason::none)
    stop_ = {reason, t_now_, law_.certified(), law_.force_bound(), events_, first_event_};
}

template <class Law>
void ExactMarch<Law>::start_flight(double t, double v, bool at_crossing) {
  resting_ = false;
  contact_.reset();
  law_.start(t, 0.0, v, at_crossing);
}

// A launch with speed w > 0 from a contact `late` before t (Contact): the flight starts at t from
// the state it has reached there, so that the impact times do not fall behind by `late` each.
template <class Law>
void ExactMarch<Law>::launch(double t, double w, double late) {
  resting_ = false;
  contact_.reset();
  if (late == 0.0) {
    law_.start(t, 0.0, w, false);
    return;
  }
  const double f = law_.force(t), gap = late * (w + f * late / 2);
  law_.start(t, gap > 0.0 ? gap : 0.0, w + f * late, false);
}

// On the floor with v = 0 at t: N = -f(t) >= 0 holds it there while f <= 0 (2-2); a force that is
// zero and falling holds it too, one that is positive lifts it at once, and so does one whose
// upward zero crossing is t itself to rounding (lift_time(t) == t).
template <class Law>
void ExactMarch<Law>::settle(double t) {
  const double f = law_.force(t);
  if (f > 0.0 || (f == 0.0 && law_.rate(t) > 0.0)) {
    start_flight(t, 0.0, f == 0.0);  // f = 0 rising: t is where f crosses 0 upward
    return;
  }
  const Lift lift = law_.lift_after(t);
  if (lift.crossing && lift.t == t) {
    start_flight(t, 0.0, true);
    return;
  }
  resting_ = true;
  contact_.reset();
  rest_start_ = t;
  lift_ = lift;
  emit(t, EventKind::stick, 0.0, 0.0);
}

template <class Law>
void ExactMarch<Law>::impact(const Contact& c, double& impulse) {
  contact_.reset();
  const double V = -c.v;
  if (V > 0.0) {
    max_speed_ = std::fmax(max_speed_, V);
    if (!first_impact_) first_impact_ = c.t;
    double after = e_ * V;
    if (after > 0.0 && e_ < 1.0 && V < kChatterCutoff * max_speed_) {
      if (const auto W = law_.chatter_window(c.t, V, e_)) {
        after = 0.0;
        chatter_window_ = *W;
      }
    }
    emit(c.t, EventKind::impact, -V, after);
    impulse += after + V;
    if (after > 0.0) {
      launch(c.t, after, c.late);
      return;
    }
  }
  settle(c.t);
}

template <class Law>
State ExactMarch<Law>::advance(double t, double& impulse) {
  // Certified search steps allowed per call: a flight takes tens (each step covers a fixed fraction
  // of the distance to the floor or more), so this is only reached by a search that stalls.
  long budget = 1'000'000;
  for (;;) {
    if (events_ > event_limit_) {
      stopped(TrackStop::Reason::events);
      return {phi_, 0.0};
    }
    if (resting_) {
      const double from = std::fmax(t_now_, rest_start_);
      while (!lift_.crossing && lift_.t <= t && budget-- > 0) lift_ = law_.lift_after(lift_.t);
      if (lift_.t > t || !lift_.crossing) {
        impulse += law_.rest_impulse(from, t);
        t_now_ = t;
        return {phi_, 0.0};
      }
      impulse += law_.rest_impulse(from, lift_.t);
      t_now_ = lift_.t;
      emit(lift_.t, EventKind::lift, 0.0, 0.0);
      start_flight(lift_.t, 0.0, true);
    }
    if (!contact_ && law_.certified() <= t) {
      contact_ = law_.search(t, budget);
      if (budget <= 0) {
        stopped(law_.failure().empty() ? TrackStop::Reason::stalled : TrackStop::Reason::law);
        if (!contact_) law_.give_up_until(t);
      }
    }
    if (contact_ && contact_->t <= t) {
      t_now_ = contact_->t;
      impact(*contact_, impulse);
      continue;
    }
    t_now_ = t;
    const State g = law_.at(t);
    // In flight the exact gap is >= 0; only rounding next to a contact can make it negative.
    return {phi_ + std::fmax(g.u, 0.0), g.v};
  }
}

}  // namespace impact
