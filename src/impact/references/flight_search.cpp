// The certified contact search of flight_search.hpp.
#include "impact/references/flight_search.hpp"

#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "impact/forces/gsl_errors.hpp"

namespace impact {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Brent's iterations: it halves the bracket at least every few iterations, so 200 is far more
// than the ~60 halvings from any bracket down to an ulp.
constexpr int kMaxBrentIterations = 200;

double amplitude(const Model& model) {
  return model.harmonic ? model.harmonic->amplitude : 0.0;
}

// x - sin x without cancellation: its Taylor series below |x| = 1/2 (terms to x^17, the next one
// below 1e-21 of the sum), the difference above, where it loses at most 5 bits.
double x_minus_sin(double x, double sin_x) {
  if (std::fabs(x) >= 0.5) return x - sin_x;
  const double y = x * x;
  double sum = 0.0, term = x;
  for (int n = 3; n <= 17; n += 2) {
    term *= y / ((n - 1) * n);
    sum += (n % 4 == 3 ? term : -term);
  }
  return sum;
}

}  // namespace

HarmonicFlight::HarmonicFlight(const Model& model, double t_a, double gap_a, double v_a)
    : t_a_(t_a), gap_a_(gap_a), v_a_(v_a), f_(model.f) {
  if (model.harmonic && model.harmonic->amplitude != 0.0) {
    const Harmonic& w = *model.harmonic;
    amplitude_ = w.amplitude;
    omega_ = w.omega;
    phase_ = w.phase;
    k_ = w.amplitude / w.omega;
    k_w_ = k_ / w.omega;
    scaled_ = !(std::fabs(k_w_) <= 0x1p900);
    sin_a_ = std::sin(theta(t_a));
    cos_a_ = std::cos(theta(t_a));
  }
}

State HarmonicFlight::at(double t) const {
  const double dt = t - t_a_;
  State s{gap_a_ + dt * (v_a_ + f_ * dt / 2), v_a_ + f_ * dt};
  if (k_ == 0.0) return s;
  if (scaled_) {  // a/omega^2 beyond 2^900: the terms of harmonic_series.hpp, a dt (...)
    const SlowAngle w = slow_angle(omega_ * dt);
    const double a_dt = amplitude_ * dt;
    s.u += a_dt * dt * (cos_a_ * w.s2 + sin_a_ * w.c2);
    s.v += a_dt * (cos_a_ * w.c1 + sin_a_ * w.s1);
    return s;
  }
  // sin x = 2 sin(x/2) cos(x/2) and 1 - cos x = 2 sin^2(x/2): one sin/cos pair, no cancellation.
  const double x = omega_ * dt, sin_half = std::sin(x / 2), cos_half = std::cos(x / 2);
  const double sin_x = 2 * sin_half * cos_half, one_minus_cos = 2 * sin_half * sin_half;
  s.u += k_w_ * (cos_a_ * x_minus_sin(x, sin_x) + sin_a_ * one_minus_cos);
  s.v += k_ * (cos_a_ * one_minus_cos + sin_a_ * sin_x);
  return s;
}

ForceBounds::ForceBounds(const Model& model) {
  const double a = std::fabs(amplitude(model)), w = model.harmonic ? model.harmonic->omega : 0.0;
  B = std::fabs(model.f) + a;
  C = a * w;
  D = a * w * w;
}

double force_at(const Model& model, double t) {
  const double a = amplitude(model);
  if (a == 0.0) return model.f;
  return model.f + a * std::sin(model.harmonic->omega * t + model.harmonic->phase);
}

double force_rate(const Model& model, double t) {
  const double a = amplitude(model);
  if (a == 0.0) return 0.0;
  const Harmonic& w = *model.harmonic;
  return a * w.omega * std::cos(w.omega * t + w.phase);
}

namespace detail {

Bracket refine_root(double (*gap)(double, void*), void* path, double lo, double hi) {
  GslErrorsAsStatus quiet;
  gsl_function F{gap, path};
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (!solver || gsl_root_fsolver_set(solver.get(), &F, lo, hi) != GSL_SUCCESS) return {lo, hi};
  for (int i = 0; i < kMaxBrentIterations; ++i) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
    lo = gsl_root_fsolver_x_lower(solver.get());
    hi = gsl_root_fsolver_x_upper(solver.get());
    if (gsl_root_test_interval(lo, hi, 0.0, 2 * std::numeric_limits<double>::epsilon()) ==
        GSL_SUCCESS)
      break;
  }
  // The upper end is <= 0 up to rounding: a contact at hi is never placed before the floor is
  // reached.
  return {lo, hi};
}

}  // namespace detail

double zero_speed_departure(const Model& model, const ForceBounds& bounds, double t,
                            bool at_crossing) {
  const double f = at_crossing ? 0.0 : force_at(model, t), rate = force_rate(model, t);
  double stretch = 0.0;
  if (f > 0.0) stretch = bounds.C > 0.0 ? 1.5 * f / bounds.C : kInfinity;
  if (f >= 0.0 && rate > 0.0) stretch = std::fmax(stretch, 2 * rate / bounds.D);
  return stretch;
}

double lift_time(const Model& model, double t) {
  const double a = std::fabs(amplitude(model));
  if (model.f + a <= 0.0) return kInfinity;
  if (a == 0.0) return t;  // a constant f > 0 never holds the particle down
  const Harmonic& w = *model.harmonic;
  // f + |A| sin(omega t + psi) with psi = phase (+ pi for A < 0) crosses 0 upward where
  // omega t + psi = asin(-f/|A|) + 2 pi n; for f > |A| it is positive everywhere.
  if (model.f >= a) return t;
  const double psi = w.phase + (w.amplitude < 0.0 ? std::numbers::pi : 0.0);
  const double crossing = std::asin(-model.f / a), two_pi = 2 * std::numbers::pi;
  const double n = std::ceil((w.omega * t + psi - crossing) / two_pi);
  return std::fmax(t, (crossing + two_pi * n - psi) / w.omega);
}

void ClosedFormLaw::start(double t, double gap, double v, bool at_crossing) {
  flight_ = HarmonicFlight(model_, t, gap, v);
  certified_ = checked_ = t;
  if (gap == 0.0 && v == 0.0) certified_ += zero_speed_departure(model_, bounds_, t, at_crossing);
}

double ClosedFormLaw::rest_impulse(double a, double b) const {
  if (!(b > a)) return 0.0;
  double value = -model_.f * (b - a);
  // cos(x) - cos(y) = 2 sin((x + y)/2) sin((y - x)/2), without cancellation for short rests.
  if (model_.harmonic && model_.harmonic->amplitude != 0.0)
    value -= harmonic_integral(*model_.harmonic, a, b);
  return value;
}

double chatter_trial_window(double e, double V, double g) {
  return 4 * e * V / (g * (1 - e));
}

std::optional<double> chatter_window_within(double e, double V, double W0, double g_min,
                                            double g_max) {
  if (!(g_min > 0.0)) return std::nullopt;
  const double rho = e * std::sqrt(g_max / g_min);
  if (!(rho < 1.0)) return std::nullopt;
  const double W = 2 * e * V / (g_min * (1 - rho));
  if (!(W <= W0)) return std::nullopt;
  return W;
}

std::optional<double> ClosedFormLaw::chatter_window(double t, double V, double e) const {
  const double g = -force(t);
  if (!(g > 0.0)) return std::nullopt;
  // |g'| <= C over the window: g stays within C W0 of g(t).
  const double W0 = chatter_trial_window(e, V, g);
  return chatter_window_within(e, V, W0, g - bounds_.C * W0, g + bounds_.C * W0);
}

}  // namespace impact
