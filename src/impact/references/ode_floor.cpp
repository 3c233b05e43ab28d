// The floor side of OdeLaw (ode_flight.hpp): the lift-off scan, the impulse of a rest and the
// chatter window, which read f on the floor.
#include <algorithm>
#include <cmath>
#include <limits>

#include "impact/forces/step_quadrature.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/references/ode_flight.hpp"

namespace impact {

namespace {

constexpr int kLiftScan = 4096;     // samples of f per lift-off scan before the track asks again
constexpr int kLiftSpacing = 8;     // lift-off scan spacing: max_step / kLiftSpacing
constexpr int kChatterSamples = 5;  // samples of f over a chatter window
// The lift-off scan's search between two samples (hidden_rise): the split point's fraction and
// the depth, which reaches 1e-9 of the spacing.
constexpr double kLiftSplit = 0.41421356237309503;  // sqrt(2) - 1
constexpr int kLiftDepth = 30;
constexpr int kLiftRescan = 8;  // samples before a lift-off's root, looking for an earlier one

}  // namespace

// A central difference, one-sided at the start of time and at the end of the run.
double OdeLaw::rate(double t) const {
  const double d = 1e-6 * std::fmax(1.0, std::fabs(t));
  const double lo = t - d >= 0.0 ? t - d : t, hi = t + d <= settings_.end ? t + d : t;
  return (force(hi) - force(lo)) / (hi - lo);
}

// A positive excursion of f inside (a, b], where f(a) <= 0 and f(b) <= 0: f at a point p a
// non-dyadic fraction in (so that a force periodic in the scan's spacing is not sampled at one
// phase), positive there or not excluded by the samples' bound max f + the largest change between
// neighbours (as for an ODE step's force bound), halves searched in order to a depth of kLiftDepth.
// Returns a bracket [lo, hi] with f(lo) <= 0 < f(hi) of the first one found.
std::optional<detail::Bracket> OdeLaw::hidden_rise(double a, double fa, double b, double fb,
                                                   int depth) const {
  const double p = a + (b - a) * kLiftSplit, fp = force(p);
  if (fp > 0.0) return detail::Bracket{a, p};
  const double bound =
      std::fmax(fa, std::fmax(fp, fb)) + std::fmax(std::fabs(fp - fa), std::fabs(fb - fp));
  if (!(bound > 0.0) || depth == 0 || !(a < p && p < b)) return std::nullopt;
  if (const auto left = hidden_rise(a, fa, p, fp, depth - 1)) return left;
  return hidden_rise(p, fp, b, fb, depth - 1);
}

// The first upward crossing of f in (a, b], where f(a) <= 0 < f(b): Brent's root of f in [a, b],
// unless a positive excursion shows before it (kLiftRescan samples of what lies before the root,
// each gap searched by hidden_rise), whose own first crossing is then the one. A force faster than
// the scan crosses several times between two of its samples (the table at 1 kHz against a
// spacing of 1.25 ms: up, down, up), and Brent may converge to any of those crossings.
double OdeLaw::first_upward(double a, double fa, double b, int depth) const {
  if (fa == 0.0) return a;
  const auto minus_f = [](double x, void* self) {
    return -static_cast<const OdeLaw*>(self)->force(x);
  };
  const detail::Bracket root = detail::refine_root(minus_f, const_cast<OdeLaw*>(this), a, b);
  if (depth == 0) return root.hi;
  double x = a, fx = fa;
  for (int k = 1; k <= kLiftRescan; ++k) {
    const double y = a + (root.lo - a) * k / kLiftRescan, fy = force(y);
    if (fy > 0.0) return first_upward(x, fx, y, depth - 1);
    if (const auto rise = hidden_rise(x, fx, y, fy, kLiftDepth))
      return first_upward(rise->lo, force(rise->lo), rise->hi, depth - 1);
    x = y;
    fx = fy;
  }
  return root.hi;
}

Lift OdeLaw::lift_after(double t) const {
  double a = t, fa = force(a);
  if (fa > 0.0) return {t, true};
  const double spacing = settings_.max_step / kLiftSpacing;
  for (int k = 1; k <= kLiftScan; ++k) {
    const double b = std::fmin(t + spacing * k, settings_.end), fb = force(b);
    if (fb > 0.0) return {first_upward(a, fa, b, kLiftDepth), true};
    if (const auto rise = hidden_rise(a, fa, b, fb, kLiftDepth))
      return {first_upward(rise->lo, force(rise->lo), rise->hi, kLiftDepth), true};
    if (b >= settings_.end) return {std::numeric_limits<double>::infinity(), true};  // none
    a = b;
    fa = fb;
  }
  return {a, false};
}

double OdeLaw::rest_impulse(double a, double b) const {
  double value = 0;
  // Gauss-Legendre 16 per piece of at most max_step, as accurate as the ODE steps; with internal
  // variables f reads z(t) on the floor, which moves over the piece.
  const Integrand on_floor{
      [](double t, void* self) { return static_cast<const OdeLaw*>(self)->force(t); },
      const_cast<OdeLaw*>(this)};
  if (floor_ && on_floor_) floor_->forget_before(a);
  for (double x = a; x < b; x += settings_.max_step) {
    const double y = std::fmin(b, x + settings_.max_step);
    value -= rate_count_ > 0 ? controlled_integral(on_floor, x, y)
                             : flight_.rhs().force.integral(x, y, rest_);
  }
  return value;
}

std::optional<double> OdeLaw::chatter_window(double t, double V, double e) const {
  const double g = -force(t);
  if (!(g > 0.0)) return std::nullopt;
  const double W0 = chatter_trial_window(e, V, g);
  if (t + W0 > settings_.end) return std::nullopt;  // f is not known beyond the run
  // The samples' range widened by the largest change between neighbours (the bound of an ODE
  // step), so that a force varying faster than the samples does not pass for a steady one.
  double g_min = g, g_max = g, previous = g, change = 0;
  for (int i = 1; i < kChatterSamples; ++i) {
    const double ti = t + W0 * i / (kChatterSamples - 1), gi = -force(ti);
    g_min = std::fmin(g_min, gi);
    g_max = std::fmax(g_max, gi);
    change = std::fmax(change, std::fabs(gi - previous));
    previous = gi;
  }
  // A force of the state: the corners of the bounces' box at each time (ode_flight.hpp).
  if (flight_.rhs().force.state_dependent() || bonds_) {
    const double height = V * V / g;
    for (int i = 0; i < kChatterSamples; ++i) {
      const double ti = t + W0 * i / (kChatterSamples - 1);
      const auto z = internal_count_ > 0 ? floor_internal(ti) : z_b_;
      for (const State corner : {State{0, -V}, State{0, V}, State{height, -V}, State{height, V}}) {
        const double gi = -force_on(ti, corner, z);
        g_min = std::fmin(g_min, gi);
        g_max = std::fmax(g_max, gi);
      }
    }
  }
  return chatter_window_within(e, V, W0, g_min - change, g_max + change);
}

}  // namespace impact
