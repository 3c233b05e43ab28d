// The event-driven exact solution for a constant or harmonic force; conventions in event_track.hpp.
#include "impact/event_track.hpp"

#include <cmath>
#include <stdexcept>

#include "impact/force.hpp"

namespace impact {

namespace {

// Certified search steps allowed per advance(): a flight takes tens (each step covers a fixed
// fraction of the distance to the floor or more), so this is only reached by a search that stalls.
constexpr long kSearchBudget = 1'000'000;

// -(integral of f over [a, b]): the impulse N = -f(t) delivers while the particle rests (2-1).
double resting_impulse(const Model& model, double a, double b) {
  return b > a ? -ForceFunction(model).integral(a, b) : 0.0;
}

}  // namespace

EventTrack::EventTrack(const Model& model, const State& initial, double t0)
    : model_(model), bounds_(model), e_(model.cor.value_or(1.0)), t_now_(t0) {
  if (!model.expression.empty())
    throw std::invalid_argument(
        "method 'exact' has no closed-form flight for a force expression; use method "
        "'event_driven'");
  const bool finite_harmonic = !model.harmonic || (std::isfinite(model.harmonic->amplitude) &&
                                                   std::isfinite(model.harmonic->omega) &&
                                                   std::isfinite(model.harmonic->phase));
  if (!std::isfinite(model.phi) || !std::isfinite(model.f) || !std::isfinite(initial.u) ||
      !std::isfinite(initial.v) || !std::isfinite(t0) || !finite_harmonic)
    throw std::invalid_argument("exact: phi, f, the harmonic force, u0 and v0 must be finite");
  if (model.harmonic && model.harmonic->amplitude != 0.0 && !(model.harmonic->omega > 0.0))
    throw std::invalid_argument("exact: the harmonic force needs omega > 0");
  if (!(e_ >= 0.0 && e_ <= 1.0)) throw std::invalid_argument("exact: COR must be in [0, 1]");
  if (initial.u < model.phi) throw std::invalid_argument("exact: u0 must be >= phi, (2-2)");
  flight_ = HarmonicFlight(model_, t0, initial.u - model.phi, initial.v);
  certified_ = t0;
  if (initial.u == model.phi && initial.v == 0.0)
    certified_ += zero_speed_departure(model_, bounds_, t0, false);
}

void EventTrack::emit(double t, EventKind kind, double v_before, double v_after) const {
  if (sink_) sink_(Event{t, kind, v_before, v_after});
}

void EventTrack::start_flight(double t, double v, bool at_crossing) {
  resting_ = false;
  contact_.reset();
  flight_ = HarmonicFlight(model_, t, 0.0, v);
  certified_ = t;
  if (v == 0.0) certified_ += zero_speed_departure(model_, bounds_, t, at_crossing);
}

// On the floor with v = 0 at t: N = -f(t) >= 0 holds it there while f <= 0 (2-2); a force that is
// zero and falling holds it too, one that is positive lifts it at once, and so does one whose
// upward zero crossing is t itself to rounding (lift_time(t) == t).
void EventTrack::settle(double t) {
  const double f = force_at(model_, t);
  if (f > 0.0 || (f == 0.0 && force_rate(model_, t) > 0.0)) {
    start_flight(t, 0.0);
    return;
  }
  const double lift = lift_time(model_, t);
  if (lift == t) {
    start_flight(t, 0.0, true);
    return;
  }
  resting_ = true;
  contact_.reset();
  rest_start_ = t;
  lift_ = lift;
  emit(t, EventKind::stick, 0.0, 0.0);
}

bool EventTrack::chatter_certified(double t, double V) {
  const double g = -force_at(model_, t);
  if (!(g > 0.0)) return false;
  const double W0 = 4 * e_ * V / (g * (1 - e_));
  const double g_min = g - bounds_.C * W0, g_max = g + bounds_.C * W0;
  if (!(g_min > 0.0)) return false;
  const double rho = e_ * std::sqrt(g_max / g_min);
  if (!(rho < 1.0)) return false;
  const double W = 2 * e_ * V / (g_min * (1 - rho));
  if (!(W <= W0)) return false;
  chatter_window_ = W;
  return true;
}

void EventTrack::impact(const Contact& c, double& impulse) {
  contact_.reset();
  const double V = -c.v;
  if (V > 0.0) {
    max_speed_ = std::fmax(max_speed_, V);
    if (!first_impact_) first_impact_ = c.t;
    double after = e_ * V;
    if (after > 0.0 && e_ < 1.0 && V < kChatterCutoff * max_speed_ && chatter_certified(c.t, V))
      after = 0.0;
    emit(c.t, EventKind::impact, -V, after);
    impulse += after + V;
    if (after > 0.0) {
      start_flight(c.t, after);
      return;
    }
  }
  settle(c.t);
}

State EventTrack::advance(double t, double& impulse) {
  long budget = kSearchBudget;
  for (;;) {
    if (resting_) {
      const double from = std::fmax(t_now_, rest_start_);
      if (lift_ > t) {
        impulse += resting_impulse(model_, from, t);
        t_now_ = t;
        return {model_.phi, 0.0};
      }
      impulse += resting_impulse(model_, from, lift_);
      t_now_ = lift_;
      emit(lift_, EventKind::lift, 0.0, 0.0);
      start_flight(lift_, 0.0, true);
    }
    if (!contact_ && certified_ <= t) {
      contact_ = search_contact(flight_, bounds_, certified_, t, budget);
      if (budget <= 0) {
        converged_ = false;
        if (!contact_) certified_ = t;
      }
    }
    if (contact_ && contact_->t <= t) {
      t_now_ = contact_->t;
      impact(*contact_, impulse);
      continue;
    }
    t_now_ = t;
    const State g = flight_.at(t);
    // In flight the exact gap is >= 0; only rounding next to a contact can make it negative.
    return {model_.phi + std::fmax(g.u, 0.0), g.v};
  }
}

}  // namespace impact
