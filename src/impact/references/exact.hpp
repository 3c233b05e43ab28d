// The exact, event-driven solution of (2-1)-(2-4) for a constant body force f: free flight
// u = u0 + v0 s + f s^2/2 between impacts, Newton's impact law v+ = -e v- at each impact (e = COR,
// or e = 1 when the scene gives no COR), and, for f < 0 and e < 1, the Zeno accumulation of impacts
// at a finite time after which the particle rests on the floor with N = -f.
// It is the reference for every error measured in this project.
//
// Everything is in closed form (no event loop, no accumulated flight times), so at(), impulse() and
// impacts_until() cost O(1) at any t, e.g. after 1e4 bounces: the bounce index comes from
// inverting t_k with a logarithm, checked against impact_time() (a bounded bisection on those
// times only right before t_inf, where rounding makes many t_k coincide). With g = -f > 0 and V1
// the speed of the first impact, impact k >= 1 has speed e^(k-1) V1 and happens at
//   t_k = t1 + (2 V1 / g) (e + e^2 + ... + e^(k-1)),   t_inf = t1 + 2 e V1 / (g (1 - e)).
// Conventions:
//  - A particle that starts on the floor moving down (u0 = phi, v0 < 0) has its first impact at
//    t1 = 0, taken as happening at 0+: at(0) is the initial state, impacts_until(0) = 0, and the
//    impact is counted in every interval (0, t], t > 0, so it lies in the first step (0, h] and
//    impulse(0, T) = v(T) - v(0) - f T holds with v(0) = v0 (the identity (4-9)).
//  - u0 = phi, v0 = 0 with f < 0 rests from t = 0 (rest_time() = 0, N = -f); with f = 0 it stays
//    put (rest_time() = 0, N = 0). u0 = phi, v0 >= 0, f >= 0 has no impact, and neither has a
//    grazing touch with zero speed (f > 0, v0^2 = 2 f (u0 - phi)).
//  - After a plastic impact (e = 0) the particle rests if f <= 0; for f > 0 it lifts off again.
//  - Past the Zeno time there were infinitely many impacts: impacts_until() then returns
//    INT64_MAX / 2, a cap larger than any count reached before t_inf.
//  - The constructor throws std::invalid_argument for non-finite data, u0 < phi, COR outside
//    [0, 1] or a force that is not constant (a harmonic part with a non-zero amplitude, an
//    expression): ExactStepper follows a harmonic force with ClosedFormMarch (exact_march.hpp). A
//    time that overflows (e.g. a Zeno time beyond DBL_MAX for a vanishing f) is treated as never
//    reached.
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>

#include "impact/methods/method_params.hpp"
#include "impact/model/model.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/references/linear_law.hpp"

namespace impact {

class ExactSolution {
 public:
  ExactSolution(const Model& model, const State& initial);

  // State at time t >= 0; v is right-continuous (the post-impact velocity at an impact instant),
  // except that at(t) for t <= 0 is the initial state (see the impact at 0+ above).
  State at(double t) const;
  // Contact impulse delivered in (t0, t1]: the impact jumps (1 + e) V_k plus the resting force -f
  // over the time spent resting; exactly 0 when neither happens in (t0, t1] or when t1 <= t0.
  double impulse(double t0, double t1) const;
  // Number of impacts in (0, t] (INT64_MAX / 2 once the Zeno time is reached).
  std::int64_t impacts_until(double t) const;
  // Time of the k-th impact, k >= 1, if there is one.
  std::optional<double> impact_time(std::int64_t k) const;
  // Speed just before the k-th impact.
  std::optional<double> impact_speed(std::int64_t k) const;
  // From this time on the particle rests on the floor (Zeno time, or the plastic impact time).
  std::optional<double> rest_time() const;
  // e of Newton's law at each impact: the COR, or 1 without one (contact_law.hpp).
  double e() const { return e_; }

  // The free flight that holds a time t with 0 < t < rest_time(): at(t) is flight_state(flight, t)
  // for every t in [begin, end), so a caller that samples in order finds it once per flight.
  struct Flight {
    std::int64_t k = 0;  // impacts before it
    double begin = std::numeric_limits<double>::infinity(), end = 0, launch = 0;
  };
  Flight flight_at(double t) const;
  State flight_state(const Flight& flight, double t) const;

 private:
  struct Impl;
  Model model_;
  State initial_;
  double e_;
  std::optional<double> t1_;  // first impact
  double V1_ = 0;             // speed just before the first impact
  std::optional<double> rest_;
};

// The exact solution as a stepper: sampled at the grid times after the state it was initialized
// with, so that it runs wherever a time-stepper does. A constant force uses ExactSolution in closed
// form (time measured from the initial grid time); a harmonic one the event-driven ClosedFormMarch
// (absolute time t = l h, which the force depends on); a linear force of the state (Model::linear)
// the event-driven LinearTrack (linear_law.hpp), its flights in closed form. An expression force is
// refused: its reference is the method event_driven.
// Sampling a grid in order costs a polynomial per sample inside one flight: the flight found for
// the previous sample is reused while the samples stay in it, and for a harmonic force sin and cos
// of omega t_l + phase advance by one rotation per step, recomputed exactly every
// kRotationAnchor samples (the recurrence drifts by about an ulp per step, ~1e-15 in between),
// except within omega (t - t_a) < 1/2 of the flight's anchor, where the flight is a polynomial in
// that angle (HarmonicFlight::at_near_anchor: the rotation's differences would cost a/omega^2
// times their rounding, 4.3e8 m at omega = 1e-24).
class ExactStepper {
 public:
  static constexpr std::int64_t kRotationAnchor = 32;

  ExactStepper(const Model& model, double h, const ExactParams&);

  // The solution from (t_l, s); throws std::invalid_argument where ExactSolution and
  // ClosedFormMarch do.
  void initialize(const State& s, std::int64_t l);

  // Samples the solution at t_{l+1}; N^l = impulse in (t_l, t_{l+1}] / h.
  StepInfo do_step(State& s, std::int64_t l) {
    if (linear_) return linear_step(s, l);
    if (track_) return harmonic_step(s, l);
    const double t0 = static_cast<double>(l - l0_) * h_, t1 = static_cast<double>(l + 1 - l0_) * h_;
    if (t0 >= flight_.begin && t1 < flight_.end) {
      s = solution_->flight_state(flight_, t1);
      return {};
    }
    if (t0 > rest_begin_) {  // at rest: N = -f (f < 0) or 0, as impulse() gives it
      s = {model_.phi, 0.0};
      StepInfo info;
      info.contact_force = rest_force_ * (t1 - t0) / h_;
      return info;
    }
    return closed_form_step(s, t0, t1);
  }

  // Receives the impacts, sticks and lifts in increasing t as the samples pass them; t is the grid
  // time (l h), also for a constant force. A constant-force Zeno sequence is reported up to the
  // impacts slower than kChatterCutoff times the first, then the stick at t_inf.
  void set_event_sink(EventSink sink);

  // Why the last step did not converge (a harmonic force's track: the events budget used up or a
  // contact search that stalled), for simulate()'s message.
  std::string failure_reason() const;

 private:
  StepInfo closed_form_step(State& s, double t0, double t1);
  StepInfo harmonic_step(State& s, std::int64_t l);
  StepInfo linear_step(State& s, std::int64_t l);
  void emit_closed_form_events(double t0, double t1) const;

  Model model_;
  double h_;
  std::int64_t max_events_ = 0, event_limit_ = 0;
  std::optional<ExactSolution> solution_;
  ExactSolution::Flight flight_;
  double rest_begin_ = std::numeric_limits<double>::infinity(), rest_force_ = 0;
  std::optional<ClosedFormMarch> track_;
  std::optional<LinearTrack> linear_;
  EventSink sink_;
  std::int64_t l0_ = 0;
  // sin and cos of omega t_l + phase for l = rotation_l_, and of omega h.
  double sin_ = 0, cos_ = 1, sin_h_ = 0, cos_h_ = 1;
  std::int64_t rotation_l_ = -1, since_anchor_ = 0;
};

}  // namespace impact
