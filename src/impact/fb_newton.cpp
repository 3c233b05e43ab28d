#include "impact/fb_newton.hpp"

#include <cmath>

#include "impact/restitution.hpp"
#include "impact/scene.hpp"

namespace impact {

FbNewtonParams FbNewton::read_params(MethodParams& p) {
  FbNewtonParams params;
  params.epsilon = p.number("epsilon", params.epsilon, 0.0, 1.0, true);
  params.tolerance = p.number("tolerance", params.tolerance, 0.0, 1e-1, true);
  params.max_iterations =
      static_cast<int>(p.integer("max_iterations", params.max_iterations, 1, 10000));
  return params;
}

// Newton on S(x) = F_eps(x - phi, N(x)) with N(x) = (2/h)((x - u^l)/h - v^l) - f = k (x - x_free),
// k = 2/h^2, x_free = u^l + h v^l + h^2 f / 2 (the position without contact force).
//
// Convergence: F_eps is concave in (a, b) (a + b minus a norm) and N is affine in x, so S is
// concave; S' = 1 + k - (a + k b)/r >= 1 + k - sqrt(1 + k^2) > 0, so S is increasing. Its root lies
// above x0 = max(x_free, phi), where S(x0) < 0, and Newton from the left of the root of an
// increasing concave function climbs monotonically without overshoot: no line search is needed.
//
// Stopping rule: the paper's absolute 1e-15 cannot be met when |N| is large (one ulp of x moves
// S by S' ulp(x) ~ k ulp(x)). We evaluate S in the cancellation-free form (2ab - eps)/(a + b + r),
// stop when |S| <= tolerance * max(1, |a|, |b|) (relative to the terms of S), or when the Newton
// update no longer changes x (x is then the double nearest the root S can resolve). Hitting
// max_iterations without either is reported as non-convergence.
StepInfo FbNewton::step(State& s, std::int64_t l) {
  const double phi = model_.phi, h = h_, eps = params_.epsilon;
  const double k = 2 / (h * h);
  const State free = flight_.predict(s, l);  // x_free = u^l + h v^l + h^2 f/2, see FreeFlight
  const double x_free = free.u;
  double x = std::fmax(x_free, phi);
  StepInfo info;
  info.converged = false;
  double a = 0, b = 0;
  for (int m = 0;; ++m) {
    a = x - phi;
    b = k * (x - x_free);
    const double r = std::sqrt(a * a + b * b + eps);
    const double S = a + b > 0 ? (2 * a * b - eps) / (a + b + r) : a + b - r;
    if (std::fabs(S) <= params_.tolerance * std::fmax(1.0, std::fmax(std::fabs(a), std::fabs(b)))) {
      info.converged = true;
      break;
    }
    if (m == params_.max_iterations) break;
    const double dS = 1 + k - (a + k * b) / r;
    const double x_next = x - S / dS;
    ++info.iterations;
    if (x_next == x) {
      info.converged = true;
      break;
    }
    x = x_next;
  }
  // N^l = k (x - x_free) >= 0 exactly, since the iterates never fall below x0 >= x_free.
  info.contact_force = b;
  if (x == x_free) {
    s = free;  // N^l = 0: the free flight goes on
    flight_.accept(l + 1, s, true);
    return info;
  }
  const double v_scheme = free.v + h * b;  // (4-1), equal to (4-2) at the solution
  // On the force branch of the complementarity pair (b > a) the step ends in contact.
  s.v = b > x - phi ? velocity_after_contact(model_, s.v, v_scheme) : v_scheme;
  s.u = x;
  flight_.accept(l + 1, s, false);
  return info;
}

}  // namespace impact
