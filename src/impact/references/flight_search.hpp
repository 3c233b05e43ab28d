// Free flight under f(t) = f + A sin(omega t + phase) and the search for its first contact with
// the floor, which never misses one, grazing ones included.
//
// The gap g = u - phi of a flight satisfies g'' = f(t), so |g''| <= B = |f| + |A| (the sup of the
// force), |g'''| <= C = |A| omega and |g''''| <= D = |A| omega^2. From a time t with g(t) > 0,
//   g(t + s) >= g(t) + g'(t) s - B s^2 / 2 > 0   for 0 <= s < s*(t) = (g' + sqrt(g'^2 + 2 B g)) /
//   B,
// so no root lies in [t, t + s*): the search steps by s*, each step certified. Once the particle
// approaches the floor fast enough, g'(t) < 0 with g'^2 >= 2 B g, the upper bound
// g(t + s) <= g + g' s + B s^2 / 2 reaches 0 at s_up = 2 g / (|g'| + sqrt(g'^2 - 2 B g)) <= |g'| /
// B, and g' <= g'(t) + B s < 0 there: g decreases strictly on [t, t + s_up] and has exactly one
// root in it, the first contact, which GSL's Brent solver refines to rounding. Near a grazing
// minimum (g' -> 0) the steps s* ~ sqrt(2 g / B) still pass it in a few steps when the minimum is
// above the floor, and when it dips below the floor, however slightly, g' < 0 with g'^2 >= 2 B g
// happens before the dip: a sign check at sample times misses such a dip, this search cannot. What
// floating point can still hide is a dip shallower than the rounding of g (~1e-16 of the terms of
// u): a search that stops progressing (t + s* == t) reports a contact there, with the speed -g'.
// A flight that leaves the floor with zero speed (g = g' = 0) is certified for its first stretch by
// the next-order bounds: g(t + s) >= f s^2 / 2 - C s^3 / 6 > 0 for s < 3 f / C when f(t) > 0, and
// g(t + s) >= f' s^3 / 6 - D s^4 / 24 > 0 for s < 4 f' / D when f(t) = 0 < f'(t) (a lift-off).
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "impact/forces/harmonic_series.hpp"
#include "impact/model/model.hpp"

namespace impact {

// The flight from the anchor (t_a, gap_a, v_a) in closed form, with the per-flight constants
// precomputed, so that a sample costs a polynomial and one (sin, cos) pair of omega t + phase.
class HarmonicFlight {
 public:
  HarmonicFlight() = default;
  HarmonicFlight(const Model& model, double t_a, double gap_a, double v_a);

  double theta(double t) const { return omega_ * t + phase_; }
  // Gap and velocity at t from sin and cos of theta(t): v = v_a + f dt + (A/omega)(cos a0 - cos),
  // g = g_a + dt (v_a + f dt/2 + (A/omega) cos a0) - (A/omega^2)(sin - sin a0).
  State at(double t, double sin_theta, double cos_theta) const {
    const double dt = t - t_a_;
    return {gap_a_ + dt * (v_a_ + f_ * dt / 2 + k_ * cos_a_) - k_w_ * (sin_theta - sin_a_),
            v_a_ + f_ * dt + k_ * (cos_a_ - cos_theta)};
  }
  // The same, written in x = omega (t - t_a) so that each term is accurate relative to its own
  // size: g = g_a + dt (v_a + f dt/2) + (A/omega^2)(cos a0 (x - sin x) + sin a0 (1 - cos x)),
  // v = v_a + f dt + (A/omega)(cos a0 (1 - cos x) + sin a0 sin x). The form above carries the
  // rounding of theta(t) ~ 1e-16 omega t, i.e. ~1e-17 m in g on a table at 10 Hz, a floor under
  // which a chatter's impact speeds (sqrt(2 |f| g)) could not decay; this one is exact to rounding
  // in g itself, so the search and the impacts use it.
  State at(double t) const;
  // The same within omega (t - t_a) < 1/2 of the anchor, without a call: a dt (...) and
  // a dt^2 (...) of harmonic_series.hpp, accurate for every omega (the two forms above carry
  // a/omega and a/omega^2 times their rounding, which a slow force makes larger than the flight).
  bool near_anchor(double t) const { return std::fabs(omega_ * (t - t_a_)) < 0.5; }
  State at_near_anchor(double t) const {
    const double dt = t - t_a_;
    const SlowAngle w = slow_angle_series(omega_ * dt);
    const double a_dt = amplitude_ * dt;
    return {gap_a_ + dt * (v_a_ + f_ * dt / 2) + a_dt * dt * (cos_a_ * w.s2 + sin_a_ * w.c2),
            v_a_ + f_ * dt + a_dt * (cos_a_ * w.c1 + sin_a_ * w.s1)};
  }
  double start() const { return t_a_; }
  // f(t) = f + A sin(theta(t)).
  double force(double t) const { return k_ == 0.0 ? f_ : f_ + amplitude_ * std::sin(theta(t)); }

 private:
  double t_a_ = 0, gap_a_ = 0, v_a_ = 0, f_ = 0, amplitude_ = 0, omega_ = 0, phase_ = 0;
  double k_ = 0, k_w_ = 0, cos_a_ = 1, sin_a_ = 0;  // A/omega, A/omega^2, cos and sin of theta(t_a)
  bool scaled_ = false;  // |A/omega^2| > 2^900 (omega -> 0): at() without k_ and k_w_
};

// The bounds on the force and its derivatives that certify the search steps (see above).
struct ForceBounds {
  explicit ForceBounds(const Model& model);
  double B = 0, C = 0, D = 0;  // sup |f|, sup |f'|, sup |f''|
};

// The first contact of a flight. Its time t is a double at or just past the root of g (g(t) <= 0),
// so the contact itself happened `late` >= 0 before t: at a late time t ~ 1e5 the doubles are
// 1.5e-11 apart, and a particle taken at t rather than at the root would land with the speed
// |v| + |f| late (a bias of one sign at every impact, which made an elastic bounce gain energy at
// each impact and the error grow as T^2). v is the velocity at the root itself, one Newton step
// back from t: v(t) - f(t) late with late = g(t) / v(t), exact to O(f' late^2); the flight after
// the impact then starts at t from the state it reached `late` after the root (ExactMarch).
struct Contact {
  double t = 0;     // the first double with g <= 0 at or past the contact
  double v = 0;     // the velocity at the contact, <= 0
  double late = 0;  // t minus the contact time, in [0, the bracket the root was refined to]
};

namespace detail {
struct Bracket {
  double lo = 0, hi = 0;
};
// The root of path.at(t).u in [lo, hi], where it decreases strictly from > 0 to <= 0 (GSL Brent),
// as the bracket it was narrowed to (hi: g <= 0 up to rounding, lo: g > 0).
Bracket refine_root(double (*gap)(double, void*), void* path, double lo, double hi);

// The contact at t, the end of a bracket [t - width, t] that holds the root, with g(t) = s.u <= 0
// and velocity s.v; f = f(t) (see Contact).
inline Contact contact_at(double t, const State& s, double f, double width) {
  if (!(s.u < 0.0 && s.v < 0.0)) return {t, std::fmin(s.v, 0.0), 0.0};
  const double late = std::fmin(s.u / s.v, width);
  return {t, std::fmin(s.v - f * late, 0.0), late};
}
}  // namespace detail

// Advances the certificate `certified` (no contact in [anchor, certified)) by certified steps until
// it passes `horizon` or reaches `end` or the first contact is found, which it returns; B bounds
// |f| over [certified, end]. `checked` is the last point where the search found g > 0 (the anchor
// at first): a root that rounding put at a certified step's end lies between it and that end.
// At most `budget` steps; budget is decreased by the steps taken (a stalled search uses it up; the
// caller reports it). Path: State at(double t) const, the gap and velocity, and
// double force(double t) const, f(t).
template <class Path>
std::optional<Contact> search_contact(const Path& path, double B, double& certified,
                                      double& checked, double horizon, long& budget,
                                      double end = std::numeric_limits<double>::infinity()) {
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  while (certified <= horizon && certified < end && budget > 0) {
    --budget;
    const double t = certified;
    const State s = path.at(t);
    const double g = s.u, v = s.v;
    if (g <= 0.0 && v <= 0.0)  // on (or, by rounding, below) the floor
      return detail::contact_at(t, s, path.force(t), t - checked);
    checked = t;
    if (v < 0.0 && v * v >= 2 * B * g) {
      // One root in [t, t + s_up], where g decreases strictly (see above).
      const double s_up = 2 * g / (-v + std::sqrt(std::fma(v, v, -2 * B * g)));
      const double hi = std::fmin(t + s_up, end);
      if (path.at(hi).u <= 0.0) {
        const auto gap = [](double x, void* self) {
          return static_cast<const Path*>(self)->at(x).u;
        };
        const detail::Bracket root = detail::refine_root(gap, const_cast<Path*>(&path), t, hi);
        return detail::contact_at(root.hi, path.at(root.hi), path.force(root.hi),
                                  root.hi - root.lo);
      }
      // The gap is still positive at hi (at end, or at t + s_up by rounding): no root before it.
      certified = hi > t ? hi : std::nextafter(t, kInfinity);
      continue;
    }
    const double gp = std::fmax(g, 0.0);
    if (B == 0.0) {
      if (v >= 0.0) certified = kInfinity;  // no force: a rising or resting particle never returns
      continue;
    }
    const double root = std::sqrt(std::fma(v, v, 2 * B * gp));
    const double step = v >= 0.0 ? (v + root) / B : 2 * gp / (root - v);
    if (!(t + step > t)) return Contact{t, std::fmin(v, 0.0)};  // stalled: a touch at rounding
    certified = std::fmin(t + step, end);
  }
  return std::nullopt;
}

// The certified first stretch of a flight that leaves the floor at t with zero speed (see above):
// 0 when neither bound certifies one, infinity when the force can never bring it back. At a
// lift-off (`at_crossing`) f(t) is 0 in exact arithmetic and taken so, whatever its rounding.
double zero_speed_departure(const Model& model, const ForceBounds& bounds, double t,
                            bool at_crossing);

// The first time >= t at which f(t) crosses 0 upward (a particle resting on the floor lifts off
// there, (2-2): N = -f(t) >= 0 no longer holds): in closed form, asin(-f/|A|) + 2 pi n; infinity
// when f + |A| <= 0 (it never lifts).
double lift_time(const Model& model, double t);

// Where a resting particle lifts off, as a law finds it: at `t` when `crossing`, else not before t
// (a law that scans f by samples says how far it looked; the track asks again from there).
struct Lift {
  double t = 0;
  bool crossing = true;
};

// f(t) and f'(t).
double force_at(const Model& model, double t);
double force_rate(const Model& model, double t);

// The chatter window W = 2 e V / (g_min (1 - rho)), rho = e sqrt(g_max / g_min), of
// exact_march.hpp for an impact of speed V, given the range [g_min, g_max] of -f over the trial
// window W0 = 4 e V / (g (1 - e)) (chatter_trial_window): nullopt unless g_min > 0, rho < 1 and
// W <= W0, so that the window the bound speaks of lies inside the one the range was taken over.
double chatter_trial_window(double e, double V, double g);
std::optional<double> chatter_window_within(double e, double V, double W0, double g_min,
                                            double g_max);

// The flights of a constant or harmonic force for ClosedFormMarch (exact_march.hpp): closed form,
// searched with the global bounds above; the chatter window is certified with C = |A| omega.
class ClosedFormLaw {
 public:
  explicit ClosedFormLaw(const Model& model) : model_(model), bounds_(model) {}

  // A flight from (t, gap, v); a zero-speed start on the floor is certified by
  // zero_speed_departure().
  void start(double t, double gap, double v, bool at_crossing);
  std::optional<Contact> search(double horizon, long& budget) {
    return search_contact(flight_, bounds_.B, certified_, checked_, horizon, budget);
  }
  State at(double t) const { return flight_.at(t); }
  // No contact of the current flight in [start, certified()).
  double certified() const { return certified_; }
  void give_up_until(double t) { certified_ = t; }
  // The bound on |f| the search steps are certified with; the closed forms do not fail.
  double force_bound() const { return bounds_.B; }
  std::string failure() const { return {}; }

  double force(double t) const { return force_at(model_, t); }
  double rate(double t) const { return force_rate(model_, t); }
  Lift lift_after(double t) const { return {impact::lift_time(model_, t), true}; }
  // -(integral of f over [a, b]): the impulse N = -f delivers while the particle rests (2-1).
  double rest_impulse(double a, double b) const;
  // The window W of exact_march.hpp for an impact of speed V at t, if certified.
  std::optional<double> chatter_window(double t, double V, double e) const;

  const HarmonicFlight& flight() const { return flight_; }

 private:
  Model model_;
  ForceBounds bounds_;
  HarmonicFlight flight_;
  double certified_ = 0, checked_ = 0;
};

}  // namespace impact
