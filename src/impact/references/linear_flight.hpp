// Free flight under a linear force of the state plus a harmonic term,
//   u'' = f(t, u, v) = -k (u - u_eq) - c v + f0 + a sin(omega t + phase),
// in closed form from an anchor (t_a, u_a, v_a): under-, critically and over-damped, k = 0, an
// inverted spring (k < 0), resonance and near-resonance, each without a special case that cancels
// (the impact oscillator, u'' = -u - cos(omega t), is k = 1, c = 0, a = -1, phase = pi/2).
//
// The form. With tau = t - t_a and w = u - u_a, w'' + c w' + k w = F + a sin(theta_a + omega tau),
// F = f0 - k (u_a - u_eq), w(0) = 0, w'(0) = v_a:
//   w = v_a p2(tau) + F Psi(tau) + R(tau),
// p1, p2 the fundamental solutions of y'' + c y' + k y = 0 (p1(0) = 1, p1'(0) = 0; p2(0) = 0,
// p2'(0) = 1; p1' = -k p2), Psi = int_0^tau p2 the response to a unit step, R the response to the
// harmonic term from rest. No equilibrium u_eq + f0/k is subtracted, so k -> 0 does not cancel.
//   - p1, p2 and Psi: e^(-c tau/2) {cos, sin/sqrt(q)} (q = k - c^2/4 > 0), the two exponentials
//     of the roots (q < 0; the slow root -k/(c/2 + sqrt(-q)) without cancellation), and where
//     |c| tau and |k| tau^2 are at most 1 their Taylor series (so that critical damping, q -> 0,
//     and short times are no special case); Psi = (1 - p1)/k only where k tau^2 > 1/4.
//   - R: within omega tau <= 1 of that regime, its Taylor series too (a short flight's
//     displacement is then accurate relative to itself, as a chatter's bounces need); elsewhere
//     the steady state y_p = P sin theta + Q cos theta (P = a (k - omega^2)/Delta,
//     Q = -a c omega/Delta, Delta = (k - omega^2)^2 + c^2 omega^2) minus the free motion from its
//     initial values; its rounding is eps |a|/sqrt(Delta), large near resonance. There (q > 0,
//     c >= 0, sqrt(Delta) < max(|k|, omega^2)/8) the Duhamel integral R = Im[a e^(i theta_a)
//     e^(i omega tau) I(tau)] with I = [tau phi1(-(mu - i beta) tau) - tau phi1(-(mu + i beta)
//     tau)] / (2 i beta), mu = c/2 + i omega, beta = sqrt(q), phi1(z) = (e^z - 1)/z, which is exact
//     at resonance (k = omega^2, c = 0: the secular growth) and accurate to eps |a| (1/omega^2 +
//     tau/omega) near it; R' = Im[a e^(i theta_a) (i omega e^(i omega tau) I + p2)].
// The forcing's angle is omega t_a + phase reduced to [-pi, pi] with omega t_a split exactly
// (fma) and 2 pi in two parts, so that a flight late in a run carries no rounding of omega t.
//
// The bound on the gap's second derivative (|u''|, the B of flight_search.hpp's certified search),
// from the state at any time s of the flight:
//   - k >= 0, c >= 0, the steady-state form: u = u_c + y_p + y_h, u_c the constant force's
//     particular solution (u_eq + f0/k, or a drift for k = 0) and y_h a free motion, for which
//     E = y_h''^2 + k y_h'^2 never increases (dE/dt = -2 c y_h''^2): for all t >= s,
//       |u''(t)| <= sqrt(y_h''(s)^2 + k y_h'(s)^2) + omega^2 |a|/sqrt(Delta) (+ |f0| if k = c = 0);
//   - k > 0, c >= 0 near resonance (the Duhamel form), over a window [s, s + W]: with y = u - u_e,
//     E = y'^2 + k y^2 has dE/dt = -2 c y'^2 + 2 a y' sin theta <= 2 |a| sqrt(E), so
//       |u''| <= sqrt(k + c^2) (sqrt(E(s)) + |a| W) + |a|;
//   - k < 0 or c < 0 (the free motion grows), over a window: with x = (y, y'),
//     |x(s + W)| <= e^(m W) (|x(s)| + |a| W), m = sqrt(1 + k^2 + c^2) >= |M| of x' = M x + ...,
//       |u''| <= sqrt(k^2 + c^2) e^(m W) (|x(s)| + |a| W) + |a|,   W <= ln 2 / m.
// Each is widened by 2^-30 relative for its own rounding. The windows are a quarter of the
// shortest time scale, 2 pi / max(omega, sqrt|k|, |c|). search_linear_contact() runs the
// certified search window by window.
#pragma once

#include <limits>
#include <optional>

#include "impact/model/model.hpp"
#include "impact/references/flight_search.hpp"

namespace impact {

struct LinearForce {
  double k = 0.0;     // spring constant (per unit time squared); < 0: an inverted spring
  double c = 0.0;     // damping (per unit time)
  double u_eq = 0.0;  // the spring's rest position
  double f0 = 0.0;    // constant force
  double amplitude = 0.0, omega = 0.0, phase = 0.0;  // a sin(omega t + phase)

  // f(t, u, v) as written above (the angle not reduced).
  double at(double t, double u, double v) const;
};

// Position, velocity and acceleration of a flight at one time.
struct FlightMotion {
  double u = 0.0;
  double v = 0.0;
  double a = 0.0;
};

// |u''| <= B over [from, until] (until may be infinity).
struct AccelerationBound {
  double B = 0.0;
  double until = std::numeric_limits<double>::infinity();
};

// Bounds on |u'''| and |u''''| over [from, until], for a flight that leaves the floor with zero
// speed (flight_search.hpp's zero_speed_departure).
struct DepartureBounds {
  double C = 0.0, D = 0.0;
  double until = 0.0;
};

class LinearFlight {
 public:
  LinearFlight() = default;
  // Throws std::invalid_argument for non-finite data or a harmonic term without omega > 0.
  LinearFlight(const LinearForce& force, double t_a, double u_a, double v_a);

  FlightMotion at(double t) const {
    FlightMotion m = relative(t);
    m.u += u_a_;
    return m;
  }
  // The same with u - u_a in place of u: the displacement since the anchor, accurate relative to
  // itself on a short flight (the gap of a bounce of height 1e-20 on a floor at 0.5).
  FlightMotion relative(double t) const;
  State state(double t) const {
    const FlightMotion m = at(t);
    return {m.u, m.v};
  }
  double start() const { return t_a_; }
  const LinearForce& force() const { return force_; }
  // Whether the harmonic response is the Duhamel integral (near resonance) or the steady state.
  bool duhamel() const { return duhamel_; }

  // A bound on |u''| from t on (see above); t >= start().
  AccelerationBound acceleration_bound(double t) const;
  // Bounds on |u'''| and |u''''| from t on, for a zero-speed departure.
  DepartureBounds departure_bounds(double t) const;

 private:
  struct Fundamental {
    double p1 = 1, p2 = 0, dp1 = 0, dp2 = 1, psi = 0;  // p1, p2, their derivatives, int p2
    bool series_response = false;  // r, dr: the harmonic response by its Taylor series
    double r = 0, dr = 0;
  };
  Fundamental fundamental(double tau) const;
  // sin and cos of the forcing's angle at tau, from those at the anchor.
  void angle(double tau, double& s, double& c) const;
  // The steady state y_p and its derivative where the forcing's angle has sine s and cosine c.
  void steady(double s, double c, double& y, double& dy) const;
  // The response to the harmonic term from rest, and its derivative, at tau (angle s, c there).
  void harmonic_response(double tau, const Fundamental& fs, double s, double c, double& r,
                         double& dr) const;
  double window() const;

  LinearForce force_;
  double t_a_ = 0, u_a_ = 0, v_a_ = 0;
  double F_ = 0;                  // f0 - k (u_a - u_eq)
  double q_ = 0;                  // k - c^2/4
  double root_ = 0;               // sqrt|q|
  double slow_ = 0, fast_ = 0;    // the roots, q < 0
  double sin_a_ = 0, cos_a_ = 1;  // the forcing's angle at the anchor
  double P_ = 0, Q_ = 0, delta_ = 1;
  bool harmonic_ = false, duhamel_ = false;
};

// The angle omega t + phase reduced to [-pi, pi] (omega t split exactly, 2 pi in two parts).
double reduced_angle(double omega, double t, double phase);

// The gap u - phi of a linear flight as flight_search.hpp's Path: the gap and velocity at t, and
// the gap's second derivative f(t). gap_a is the gap at the anchor, as the caller knows it (0 for
// a launch from the floor): the gap is gap_a + (u - u_a), so that it is not rounded to the ulps of
// phi.
struct LinearGap {
  const LinearFlight* flight = nullptr;
  double gap_a = 0.0;
  State at(double t) const {
    const FlightMotion m = flight->relative(t);
    return {gap_a + m.u, m.v};
  }
  double force(double t) const { return flight->relative(t).a; }
};

// search_contact of flight_search.hpp over the flight's windows, each with its bound: the first
// contact of the flight with the floor (the anchor's gap gap_a, see LinearGap), or nullopt once
// `certified` (no contact before it) passes `horizon` or the budget is used up.
std::optional<Contact> search_linear_contact(const LinearFlight& flight, double gap_a,
                                             double& certified, double& checked, double horizon,
                                             long& budget);

}  // namespace impact
