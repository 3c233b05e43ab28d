#include "impact/steppers/fb_newton.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace impact {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The root of the smoothed equation in closed form, to verify Newton's answer. F_eps(a, b) = 0 is
// 2 a b = eps with a + b > 0; with a = x (the gap) and b = k (x - d), d the free-flight gap,
// k = 2/h^2, it is the quadratic a (a - d) = eps h^2 / 4, whose positive root is
// a = (d + s)/2, s = sqrt(d^2 + q^2), q = h sqrt(eps), and then b = eps / (s + d) for d >= 0 and
// b = (s - d) / h^2 for d < 0: each a sum of non-negative terms, without cancellation.
struct Root {
  double a, b;
};
Root smoothed_root(double d, double h, double eps) {
  const double q = h * std::sqrt(eps);
  double s = std::sqrt(d * d + q * q);
  if (!std::isfinite(s)) s = std::hypot(d, q);  // d^2 overflows
  if (d >= 0) return {0.5 * (d + s), eps / (s + d)};
  return {q * (q / (2 * (s - d))), (s - d) / (h * h)};
}

}  // namespace

void FbNewton::initialize(const State& s, std::int64_t l) {
  gap_ = {s.u - model_.phi, s.v};
  flight_.start(l, gap_);
  repeats_.reset();
}

// Newton on S(x) = F_eps(x, N(x)) with x = u^{l+1} - phi (the gap) and
// N(x) = (2/h)((x - g^l)/h - v^l) - f^l = k (x - x_free), k = 2/h^2,
// x_free = g^l + h v^l + h^2 f^l / 2
// (the gap without contact force).
//
// Gap coordinates: the step works on g = u - phi and carries g from step to step, adding phi only
// to the state it returns. Rounding u to the floor's ulp (1.2e-10 at phi = 1e6) would otherwise
// feed back: N = k (x - x_free) turns one ulp of u into a velocity jump h k ulp = 2 ulp / h (0.23
// at h = 1e-9), which kicked a particle resting on a floor at 1e6 up (experiments/stability). For
// phi = 0 the arithmetic is the same as in u.
//
// Convergence: F_eps is concave in (a, b) (a + b minus a norm) and N is affine in x, so S is
// concave; S' = 1 + k - (a + k b)/r >= 1 + k - sqrt(1 + k^2) > 0, so S is increasing. Its root lies
// above x0 = max(x_free, 0), where S(x0) < 0, and Newton from the left of the root of an
// increasing concave function climbs monotonically without overshoot: no line search is needed.
// In floating point the last update can overshoot the root by an ulp and the next one come back,
// a cycle between two neighbouring doubles that ran into max_iterations (seen with COR and
// eps ~ 1e-4, where one ulp of x moves S by 1e-14 > tolerance); the bracket ends it.
//
// Stopping rule: the paper's absolute 1e-15 cannot be met when |N| is large (one ulp of x moves
// S by S' ulp(x) ~ k ulp(x)). We evaluate S in the cancellation-free form (2ab - eps)/(a + b + r),
// stop when |S| <= tolerance * max(1, |a|, |b|) (relative to the terms of S), or when the Newton
// update no longer changes x or leaves the bracket (x is then the double nearest the root S can
// resolve). Hitting max_iterations without either is reported as non-convergence.
//
// Safeguard: the relative rule can stop far from the root where the smoothing dominates. When the
// free flight ends within h sqrt(eps) of the floor the root has N ~ sqrt(eps)/h, and Newton climbs
// towards it from N ~ sqrt(eps), doubling N at each iteration, where S ~ -eps / (2N): the relative
// rule accepts that S once N ~ sqrt(eps / (2 tolerance)) (eps / (2 tolerance) when that is below
// 1), after at most log2(1 / sqrt(2 tolerance)) = 24 doublings at the default tolerance, short of
// the root (a factor 30 at eps = 1e-2, h = 1e-9: a velocity error of 0.1). The smoothing moves
// the velocity by up to sqrt(eps) (h N <= sqrt(eps) at the root when x_free >= 0), so a step whose
// velocity h N is more than kSmoothingCheck sqrt(eps) (plus rounding) away from that of the
// closed-form root (smoothed_root) takes the closed-form root instead. A step that stopped at
// x0 = 0 without iterating (x_free < 0: the floor is reached within the step) is off by
// h eps / (2 |x_free|) in velocity (closed form), within that bound when
// |x_free| >= h sqrt(eps) / (2 kSmoothingCheck): it needs no check, which keeps the check off the
// common contact step.
StepInfo FbNewton::do_step(State& s, std::int64_t l) {
  constexpr double kSmoothingCheck = 0.1;
  const double phi = model_.phi, h = h_, eps = params_.epsilon;
  const double k = 2 / (h * h);
  const bool paper = params_.free_flight == FreeFlightForm::paper;
  // x_free = g^l + h v^l + h^2 f^l/2, f^l the step's discrete force (scheme_flight.hpp)
  State free = flight_.step(l);
  if (paper) free = paper_free_step(gap_, flight_.step_force(), h);
  const double x_free = free.u;
  double x = std::fmax(x_free, 0.0);
  StepInfo info;
  info.converged = false;
  double a = 0, b = 0, S = 0;
  // The bracket: the largest x seen with S(x) < 0 and the smallest with S(x) > 0, and their S.
  double below = -kInfinity, above = kInfinity, S_below = 0, S_above = 0;
  for (int m = 0;; ++m) {
    a = x;
    b = k * (x - x_free);
    const double r = std::sqrt(a * a + b * b + eps);
    S = a + b > 0 ? (2 * a * b - eps) / (a + b + r) : a + b - r;
    threshold_ = params_.tolerance * std::fmax(1.0, std::fmax(std::fabs(a), std::fabs(b)));
    if (std::fabs(S) <= threshold_) {
      info.converged = true;
      break;
    }
    (S < 0 ? below : above) = x;
    (S < 0 ? S_below : S_above) = S;
    if (m == params_.max_iterations) break;
    const double dS = 1 + k - (a + k * b) / r;
    const double x_next = x - S / dS;
    ++info.iterations;
    if (x_next == x) {
      info.converged = true;
      break;
    }
    if (!(x_next > below && x_next < above)) {
      // Rounding made Newton overshoot the root and come back to (or past) the other end of the
      // bracket: the root lies between two doubles Newton cannot separate, so x is the end whose
      // residual is smaller.
      x = std::fabs(S_below) <= std::fabs(S_above) ? below : above;
      a = x;
      b = k * (x - x_free);
      info.converged = true;
      break;
    }
    x = x_next;
  }
  residual_ = S;
  force_ = b;
  iterations_ = info.iterations;
  if (!info.converged) return info;  // s is left at t_l; simulate() reports the failure
  // In free flight (b = 0) Newton stopped at x_free, where S ~ -eps / (2 x_free).
  const bool floor_within_step =
      info.iterations == 0 && x_free <= -h * sqrt_eps_ / (2 * kSmoothingCheck);
  if (b > 0 && !floor_within_step) {
    const Root root = smoothed_root(x_free, h, eps);
    if (h * std::fabs(b - root.b) >
        kSmoothingCheck * sqrt_eps_ + 1e-12 * (std::fabs(free.v) + h * root.b)) {
      x = root.a;
      b = root.b;
    }
  }
  // N^l = k (x - x_free) >= 0 exactly, since the iterates never fall below x0 >= x_free; N^l = 0
  // (x = x_free) is free flight.
  info.contact_force = b;
  if (b == 0) {
    gap_ = free;  // N^l = 0: the free flight goes on
  } else {
    // (4-1), equal to (4-2) at the solution; `paper` evaluates (4-2) as printed.
    const double v_scheme = paper ? 2 / h * (x - gap_.u) - gap_.v : free.v + h * b;
    // The COR law acts where the unsmoothed (4-3) has N^l > 0, i.e. where the free flight ends
    // below the floor: the same steps as in direct, not those the smoothing alone pushes.
    const double v_before = gap_.v;
    gap_.u = x;
    velocity_after_step(restitution_.has_cor, restitution_.cor, restitution_.fixed_point,
                        x_free < 0, v_before, v_scheme, gap_.v);
    flight_.start(l + 1, gap_);
    if (flight_.constant_force()) repeats_.contact(l, gap_);
    // Newton's law replaced (4-1)'s velocity: the floor's impulse is the jump over the free flight.
    if (restitution_.has_cor && x_free < 0) restitute(info, gap_.v, free.v, h);
  }
  s = {phi + gap_.u, gap_.v};
  return info;
}

std::string FbNewton::failure_reason() const {
  std::ostringstream msg;
  msg.precision(3);
  msg << "Newton on the smoothed Fischer-Burmeister equation (5-3) stopped after " << iterations_
      << " iterations (method.max_iterations) with |S| = " << std::fabs(residual_)
      << " > tolerance * max(1, |a|, |b|) = " << threshold_ << ", N = " << force_
      << "; where the smoothing dominates, Newton doubles N at each iteration from sqrt(eps), "
         "which takes up to log2(1 / sqrt(2 tolerance)) + 2 iterations";
  return msg.str();
}

}  // namespace impact
