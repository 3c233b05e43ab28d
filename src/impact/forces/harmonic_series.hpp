// The harmonic part a sin(omega t + phase) of a free flight, in forms accurate for every omega.
//
// Over a time s from an anchor at theta_a the force turns by x = omega s, and the flight gains
//   v: (a/omega)(cos theta_a (1 - cos x) + sin theta_a sin x),
//   u: (a/omega^2)(cos theta_a (x - sin x) + sin theta_a (1 - cos x)),
// forms whose factors a/omega and a/omega^2 grow without bound as omega -> 0 while the flight's
// terms vanish: written with the differences of sines and cosines of the absolute angles (the
// phasor of scheme_flight.hpp, exact's rotation), they carry the rounding of those, ~1e-16, times
// a/omega^2 (524 287 m of u after 2 s at omega = 1e-20), and a/omega^2 overflows below
// omega ~ 1e-154. Divided by the powers of x that keep them O(1), the same terms are
//   v: a s (cos theta_a C1 + sin theta_a S1),   u: a s^2 (cos theta_a S2 + sin theta_a C2),
// with S1 = sin x / x, C1 = (1 - cos x) / x, C2 = (1 - cos x) / x^2, S2 = (x - sin x) / x^2, each
// accurate to rounding: by its Taylor series for |x| < 1/2 (to x^17; the first term left out is
// below 1e-22 of the sum), from sin x and cos x above (losing a few bits to the differences
// 1 - cos x >= 0.12 and x - sin x >= 0.02). At omega = 0 they are the constant force
// a sin(phase): S1 = 1, C2 = 1/2, C1 = S2 = 0.
#pragma once

#include <array>
#include <cmath>

#include "impact/model/model.hpp"

namespace impact {

// The phase omega h below which the time-steppers (scheme_flight.hpp) write a harmonic force in
// these forms. Above it they keep the phasor's closed forms, whose rounding (a/omega^2) 2 d, with
// d = 8.7e-15 the phasor's (SchemeFlight::kHarmonicTermError), stays within the scheme's own
// truncation bound a h^2/6 while omega h >= sqrt(12 d) = 3.2e-7; every shipped scene has
// omega h >= 6e-5 and keeps its numbers bit for bit. (exact, whose own accuracy is rounding,
// samples every flight in these forms within x < 1/2 of its anchor: HarmonicFlight.)
inline constexpr double kSlowPhase = 3.2e-7;

// S1, C1, C2, S2 of x (above).
struct SlowAngle {
  double s1 = 1, c1 = 0, c2 = 0.5, s2 = 0;
};

namespace detail {
// 1 / (2k + n)! for k = 0..8.
constexpr std::array<double, 9> inverse_factorials(int n) {
  std::array<double, 9> c{};
  double factorial = 1;
  for (int j = 2; j <= n; ++j) factorial *= j;
  for (int k = 0; k < 9; ++k) {
    c[k] = 1 / factorial;
    factorial *= (2 * k + n + 1) * (2 * k + n + 2);
  }
  return c;
}
// sum_k (-1)^k c_k y^k, by Horner.
[[gnu::always_inline]] inline double alternating(const std::array<double, 9>& c, double y) {
  double sum = c[8];
  for (int k = 7; k >= 0; --k) sum = c[k] - y * sum;
  return sum;
}
inline constexpr std::array<double, 9> kSinOverX = inverse_factorials(1),
                                       kVersOverX2 = inverse_factorials(2),
                                       kSinRestOverX3 = inverse_factorials(3);
}  // namespace detail

// The terms for |x| < 1/2, by their series in y = x^2 (no call: it runs in the time-steppers'
// loops).
[[gnu::always_inline]] inline SlowAngle slow_angle_series(double x) {
  const double y = x * x;
  SlowAngle a;
  a.s1 = detail::alternating(detail::kSinOverX, y);
  a.c2 = detail::alternating(detail::kVersOverX2, y);
  a.c1 = x * a.c2;
  a.s2 = x * detail::alternating(detail::kSinRestOverX3, y);
  return a;
}

// The terms from sin x and cos x, for |x| >= 1/2.
[[gnu::always_inline]] inline SlowAngle slow_angle(double x, double sin_x, double cos_x) {
  SlowAngle a;
  a.s1 = sin_x / x;
  a.c1 = (1 - cos_x) / x;
  a.c2 = a.c1 / x;
  a.s2 = (x - sin_x) / (x * x);
  return a;
}

// The terms at x, for any x (a call to sin and cos above 1/2).
inline SlowAngle slow_angle(double x) {
  return std::fabs(x) < 0.5 ? slow_angle_series(x) : slow_angle(x, std::sin(x), std::cos(x));
}

// The integral of a sin(omega t + phase) over [t0, t1]: (a/omega) 2 sin(mid) sin(half) with
// mid = omega (t0 + t1)/2 + phase and half = omega (t1 - t0)/2 (no cancellation for short
// intervals), or a (t1 - t0) sin(mid) sin(half)/half where a/omega overflows (omega -> 0).
inline double harmonic_integral(const Harmonic& w, double t0, double t1) {
  const double mid = w.omega * (t0 + t1) / 2 + w.phase, half = w.omega * (t1 - t0) / 2;
  const double k = w.amplitude / w.omega;
  if (std::isfinite(k)) return k * 2 * std::sin(mid) * std::sin(half);
  return w.amplitude * (t1 - t0) * std::sin(mid) * (half == 0.0 ? 1.0 : std::sin(half) / half);
}

}  // namespace impact
