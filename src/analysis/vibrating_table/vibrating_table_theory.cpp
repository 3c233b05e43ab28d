#include "analysis/vibrating_table/vibrating_table_theory.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multiroots.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_vector.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "impact/forces/force.hpp"
#include "impact/forces/gsl_errors.hpp"
#include "impact/model/model.hpp"

namespace impact::vibrating_table {

namespace {

constexpr double kTwoPi = 2 * std::numbers::pi;

// The dimensionless force -1 + Gamma sin(tau) as the core's harmonic body force (omega = 1).
ForceFunction table_force(double gamma) {
  Model model;
  model.f = -1.0;
  model.harmonic = Harmonic{gamma, 1.0, 0.0};
  return ForceFunction(model);
}

// The root of F in [lo, hi], where F changes sign once, by GSL's Brent solver until the bracket is
// within epsabs + epsrel |x| (at most 200 iterations: the bracket shrinks by at least half every
// few). F must not throw (GSL is C): a callback reports a failure as NaN, which ends here as an
// exception.
double brent_root(gsl_function& F, double lo, double hi, double epsabs, double epsrel) {
  const GslErrorsAsStatus errors;
  std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  if (gsl_root_fsolver_set(solver.get(), &F, lo, hi) != GSL_SUCCESS)
    throw std::runtime_error("brent_root: the interval does not bracket a root");
  for (int i = 0; i < 200; ++i) {
    if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS)
      throw std::runtime_error("brent_root: the function is not finite in the bracket");
    if (gsl_root_test_interval(gsl_root_fsolver_x_lower(solver.get()),
                               gsl_root_fsolver_x_upper(solver.get()), epsabs,
                               epsrel) == GSL_SUCCESS)
      break;
  }
  return gsl_root_fsolver_root(solver.get());
}

// The first impact in (lo, hi], where the gap u(s) = flight(start, t0, t0 + s).u is monotone and
// u(lo) > 0 >= u(hi): to a few ulp of s.
double impact_root(const ForceFunction& force, const State& start, double t0, double lo,
                   double hi) {
  struct Flight {
    const ForceFunction* force;
    State start;
    double t0;
  } flight{&force, start, t0};
  gsl_function gap{[](double s, void* p) {
                     const auto* f = static_cast<const Flight*>(p);
                     return f->force->flight(f->start, f->t0, f->t0 + s).u;
                   },
                   &flight};
  return brent_root(gap, lo, hi, 0.0, 4 * std::numeric_limits<double>::epsilon());
}

}  // namespace

double wrap_phase(double tau) {
  const double r = std::fmod(tau, kTwoPi);
  return r < 0 ? r + kTwoPi : r;
}

double period_one_existence_threshold(double e, int n) {
  return std::numbers::pi * n * (1 - e) / (1 + e);
}

double period_doubling_threshold(double e, int n) {
  const double g1 = period_one_existence_threshold(e, n);
  const double s = 2 * (1 + e * e) / ((1 + e) * (1 + e));
  return std::sqrt(g1 * g1 + s * s);
}

std::optional<PeriodOneOrbit> period_one_orbit(double gamma, double e, int n, bool stable_branch) {
  const double g1 = period_one_existence_threshold(e, n);
  if (!(gamma >= g1) || !(e > 0 && e <= 1) || n < 1) return std::nullopt;
  const double c = g1 / gamma;
  const double sine = (stable_branch ? 1.0 : -1.0) * std::sqrt(std::max(0.0, 1 - c * c));
  PeriodOneOrbit orbit;
  orbit.impact.phase = wrap_phase(std::atan2(sine, c));
  orbit.impact.speed = kTwoPi * n * e / (1 + e);
  orbit.impact_speed = kTwoPi * n / (1 + e);
  // d(phase', w') / d(phase, w) with s = Gamma sin(phase), a = 1 + e (vibrating_table.md, (T-7)).
  const double s = gamma * sine, a = 1 + e;
  orbit.jacobian = {1 - a * s, a, -e * a * s * (1 - s), e * (a * (1 - s) - 1)};
  orbit.eigenvalues = eigenvalues_2x2(orbit.jacobian);
  return orbit;
}

std::array<std::complex<double>, 2> eigenvalues_2x2(const std::array<double, 4>& m) {
  const double trace = m[0] + m[3], det = m[0] * m[3] - m[1] * m[2];
  const std::complex<double> root = std::sqrt(std::complex<double>(trace * trace / 4 - det));
  return {trace / 2 - root, trace / 2 + root};
}

std::optional<MapStep> impact_map(const TableImpact& impact, double gamma, double e,
                                  double max_flight) {
  const ForceFunction force = table_force(gamma);
  const double bound = *force.bound();  // |u''| <= 1 + |Gamma| in flight
  const State start{0.0, impact.speed};
  const double t0 = impact.phase;
  // March s forward with steps that cannot pass a root: from (u, v) = (u(s), u'(s)) the gap stays
  // above u + v d - bound d^2 / 2, positive for d below its root. Once the gap is falling fast
  // enough that even u + v d + bound d^2 / 2 reaches 0 (at d_up, before u' could turn back up),
  // [s, s + d_up] holds exactly one root: the first impact.
  double s = 0.0;
  for (int step = 0; step < 1000000 && s <= max_flight; ++step) {
    const State now = force.flight(start, t0, t0 + s);
    const double u = std::max(now.u, 0.0), v = now.v;
    if (v < 0 && v * v >= 2 * bound * u && s > 0) {
      const double d_up = (-v - std::sqrt(v * v - 2 * bound * u)) / bound;
      const double hit = u == 0 ? s : impact_root(force, start, t0, s, s + d_up);
      const State before = force.flight(start, t0, t0 + hit);
      return MapStep{{wrap_phase(t0 + hit), -e * before.v}, hit};
    }
    const double d_safe = (v + std::sqrt(v * v + 2 * bound * u)) / bound;
    if (!(d_safe > 0)) return std::nullopt;  // at rest on the table with u'' <= 0
    s += d_safe;
  }
  return std::nullopt;
}

std::array<double, 4> map_jacobian(const TableImpact& impact, double gamma, double e) {
  // Central differences with steps ~ eps^(1/3) of the scale: truncation and rounding ~ 1e-10.
  const double dp = 1e-5, dw = 1e-5 * std::max(1.0, impact.speed);
  const auto image = [&](double phase, double speed) {
    const std::optional<MapStep> m = impact_map({phase, speed}, gamma, e);
    if (!m) throw std::runtime_error("impact_map: no next impact near the fixed point");
    return std::array<double, 2>{phase + m->flight, m->next.speed};
  };
  const auto p_plus = image(impact.phase + dp, impact.speed);
  const auto p_minus = image(impact.phase - dp, impact.speed);
  const auto w_plus = image(impact.phase, impact.speed + dw);
  const auto w_minus = image(impact.phase, impact.speed - dw);
  return {(p_plus[0] - p_minus[0]) / (2 * dp), (w_plus[0] - w_minus[0]) / (2 * dw),
          (p_plus[1] - p_minus[1]) / (2 * dp), (w_plus[1] - w_minus[1]) / (2 * dw)};
}

std::optional<TableImpact> map_fixed_point(const TableImpact& guess, double gamma, double e,
                                           int n) {
  struct Problem {
    double gamma, e;
    int n;
  } problem{gamma, e, n};
  // The residual of a fixed point of the n-period return: (flight - 2 pi n, w' - w).
  const auto residual = [](const gsl_vector* x, void* p, gsl_vector* out) {
    const auto* q = static_cast<const Problem*>(p);
    const double phase = gsl_vector_get(x, 0), speed = gsl_vector_get(x, 1);
    if (!(speed > 0)) return static_cast<int>(GSL_EDOM);
    std::optional<MapStep> m;
    try {
      m = impact_map({wrap_phase(phase), speed}, q->gamma, q->e);
    } catch (const std::exception&) {
      return static_cast<int>(GSL_EDOM);  // no exception may cross GSL's C frames
    }
    if (!m) return static_cast<int>(GSL_EDOM);
    gsl_vector_set(out, 0, m->flight - kTwoPi * q->n);
    gsl_vector_set(out, 1, m->next.speed - speed);
    return static_cast<int>(GSL_SUCCESS);
  };
  gsl_multiroot_function F{residual, 2, &problem};
  const GslErrorsAsStatus errors;
  std::unique_ptr<gsl_vector, decltype(&gsl_vector_free)> x(gsl_vector_alloc(2), &gsl_vector_free);
  gsl_vector_set(x.get(), 0, guess.phase);
  gsl_vector_set(x.get(), 1, guess.speed);
  std::unique_ptr<gsl_multiroot_fsolver, decltype(&gsl_multiroot_fsolver_free)> solver(
      gsl_multiroot_fsolver_alloc(gsl_multiroot_fsolver_hybrids, 2), &gsl_multiroot_fsolver_free);
  if (gsl_multiroot_fsolver_set(solver.get(), &F, x.get()) != GSL_SUCCESS) return std::nullopt;
  for (int i = 0; i < 200; ++i) {
    const int status = gsl_multiroot_fsolver_iterate(solver.get());
    if (gsl_multiroot_test_residual(solver.get()->f, 1e-13) == GSL_SUCCESS)
      return TableImpact{wrap_phase(gsl_vector_get(solver.get()->x, 0)),
                         gsl_vector_get(solver.get()->x, 1)};
    if (status != GSL_SUCCESS) break;
  }
  return std::nullopt;
}

double numeric_period_doubling_threshold(double e, int n, double gamma_from, double step) {
  // 1 + trace + det at the numeric fixed point: positive while both eigenvalues exceed -1. The
  // multiroot starts from the closed-form orbit, shifted, so that it must find the point itself.
  // NaN where there is no orbit or a solver fails (it is called from GSL's C code).
  const auto margin = [&](double gamma) {
    const std::optional<PeriodOneOrbit> orbit = period_one_orbit(gamma, e, n);
    if (!orbit) return std::numeric_limits<double>::quiet_NaN();
    const TableImpact guess{orbit->impact.phase + 0.05, orbit->impact.speed * 1.02};
    const std::optional<TableImpact> fixed = map_fixed_point(guess, gamma, e, n);
    if (!fixed) return std::numeric_limits<double>::quiet_NaN();
    try {
      const std::array<double, 4> j = map_jacobian(*fixed, gamma, e);
      return 1 + (j[0] + j[3]) + (j[0] * j[3] - j[1] * j[2]);
    } catch (const std::exception&) {
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
  double lo = gamma_from, hi = gamma_from;
  for (int i = 0; i < 1000 && margin(hi) > 0; ++i) {
    lo = hi;
    hi += step;
  }
  if (!(margin(hi) <= 0))
    throw std::runtime_error("numeric_period_doubling_threshold: no sign change in the scan");
  struct Margin {
    const decltype(margin)* m;
  } fn{&margin};
  gsl_function F{[](double g, void* p) { return (*static_cast<Margin*>(p)->m)(g); }, &fn};
  return brent_root(F, lo, hi, 1e-12, 0.0);
}

}  // namespace impact::vibrating_table
