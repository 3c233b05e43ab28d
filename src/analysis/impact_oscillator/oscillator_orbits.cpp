#include "analysis/impact_oscillator/oscillator_orbits.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "impact/format.hpp"

namespace impact::impact_oscillator {

namespace {

// The perturbation of a branch run, and the level below which it must have decayed.
constexpr double kBranchKick = 1e-3, kBranchSettled = 1e-13;

std::vector<Event> impacts_of(const std::vector<Event>& events) {
  std::vector<Event> out;
  for (const Event& e : events)
    if (e.kind == EventKind::impact) out.push_back(e);
  return out;
}

// Least-squares slope of y against x.
double slope(const std::vector<double>& x, const std::vector<double>& y) {
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return c1;
}

double bisect(const std::function<double(double)>& f, double lo, double hi, double tolerance) {
  const bool low_positive = f(lo) > 0;
  if ((f(hi) > 0) == low_positive)
    throw std::runtime_error("bisection: no sign change of the growth rate in [" + round_trip(lo) +
                             ", " + round_trip(hi) + "]");
  while (hi - lo > tolerance) {
    const double mid = (lo + hi) / 2;
    ((f(mid) > 0) == low_positive ? lo : hi) = mid;
  }
  return (lo + hi) / 2;
}

// The root of the linear fit of (1 - lambda_1)^2 against x.
double extrapolate(const std::function<double(double)>& multiplier, double near,
                   const std::vector<double>& offsets) {
  std::vector<double> x, y;
  for (double d : offsets) {
    x.push_back(d);
    const double gap = 1 - multiplier(near + d);
    y.push_back(gap * gap);
  }
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return near - c0 / c1;
}

// By value: callers pass period_one_orbit's temporary, which a reference would outlive.
PeriodOneOrbit require_orbit(const std::optional<PeriodOneOrbit>& orbit, const Oscillator& o) {
  if (!orbit)
    throw std::runtime_error("no period-one orbit at omega = " + round_trip(o.omega) +
                             ", r = " + round_trip(o.r) + ", sigma = " + round_trip(o.sigma));
  return *orbit;
}

}  // namespace

OrbitCheck check_run(const Oscillator& o, const State& initial, double T, Runner runner) {
  OrbitCheck c;
  c.o = o;
  c.orbit = require_orbit(period_one_orbit(o), o);
  c.multiplier = leading_multiplier(orbit_trace(o, c.orbit.V), o.r);
  const std::vector<Event> impacts =
      impacts_of(runner == Runner::reference ? run_track(o, initial, T).events
                                             : event_driven_events(o, initial, T, T / 64));
  c.impacts = static_cast<int>(impacts.size());
  if (impacts.empty()) throw std::runtime_error("check_run: no impact");
  const Event& last = impacts.back();
  c.V = -last.v_before;
  c.phase = impact_phase(last.t, o.omega);
  c.V_error = c.V - c.orbit.V;
  c.phase_error = std::remainder(c.phase - c.orbit.t0, o.period());
  return c;
}

State orbit_state_at_zero(const Oscillator& o, const PeriodOneOrbit& orbit, double kick) {
  const LinearFlight flight(oscillator_force(o.omega), orbit.t0 - orbit.T, o.phi(), o.r * orbit.V);
  State s = flight.state(0.0);
  s.v += kick * orbit.V;
  return s;
}

int branch_impacts(double multiplier) {
  const double k = std::log(kBranchSettled / kBranchKick) / std::log(multiplier);
  return std::clamp(static_cast<int>(std::ceil(k)), 100, 4000);
}

OrbitCheck check_branch_point(const Oscillator& o, Runner runner) {
  const PeriodOneOrbit orbit = require_orbit(period_one_orbit(o), o);
  const double multiplier = leading_multiplier(orbit_trace(o, orbit.V), o.r);
  // The last impact kept is the k-th: the run ends half a period after it.
  const double T = orbit.t0 + (branch_impacts(multiplier) + 0.5) * orbit.T;
  return check_run(o, orbit_state_at_zero(o, orbit, kBranchKick), T, runner);
}

BranchAgreement agreement(const std::vector<OrbitCheck>& checks) {
  BranchAgreement a;
  for (const OrbitCheck& c : checks) {
    a.V = std::fmax(a.V, std::fabs(c.V_error));
    a.phase = std::fmax(a.phase, std::fabs(c.phase_error));
    ++a.points;
  }
  return a;
}

double growth_rate(const Oscillator& o, int N, int K, double eps) {
  const PeriodOneOrbit orbit = require_orbit(period_one_orbit(o), o);
  Impact x{orbit.t0 + eps, orbit.V + eps};
  std::vector<double> V{x.V};
  for (int i = 0; i < N; ++i) {
    const auto next = impact_map(o, x, 10 * orbit.T);
    if (!next) throw std::runtime_error("growth_rate: the map found no impact");
    x = *next;
    V.push_back(x.V);
  }
  std::vector<double> k, log_difference;
  for (int i = K; i < N; ++i) {
    k.push_back(i);
    log_difference.push_back(std::log(std::fabs(V[i + 1] - V[i])));
  }
  return slope(k, log_difference);
}

namespace {
// The recipes' settings (paper_notes/impact_oscillator.md): a period doubling from runs of 300
// impacts kicked by 1e-5, fitted over impacts 150..300 (the second multiplier r^2/lambda_1 is gone
// by then); a saddle-node from runs kicked by 1e-7, fitted over impacts 100..300.
constexpr int kRunImpacts = 300, kPdFitFrom = 150, kSnFitFrom = 100;
constexpr double kPdKick = 1e-5, kSnKick = 1e-7;

// What the bisection and the extrapolation read off the runs: the growth rate of a kicked orbit
// (zero at a period doubling) and its exponential (zero at a saddle-node).
double period_doubling_rate(const Oscillator& o) {
  return growth_rate(o, kRunImpacts, kPdFitFrom, kPdKick);
}
double saddle_node_factor(const Oscillator& o) {
  return std::exp(growth_rate(o, kRunImpacts, kSnFitFrom, kSnKick));
}
}  // namespace

double bisect_period_doubling_sigma(double omega, double r, double lo, double hi,
                                    double tolerance) {
  return bisect(
      [&](double sigma) {
        return period_doubling_rate({omega, r, sigma});
      },
      lo, hi, tolerance);
}

double bisect_period_doubling_omega(double sigma, double r, double lo, double hi,
                                    double tolerance) {
  return bisect(
      [&](double omega) {
        return period_doubling_rate({omega, r, sigma});
      },
      lo, hi, tolerance);
}

double extrapolate_saddle_node_sigma(double omega, double r, double sigma_near,
                                     const std::vector<double>& offsets) {
  return extrapolate(
      [&](double sigma) {
        return saddle_node_factor({omega, r, sigma});
      },
      sigma_near, offsets);
}

double extrapolate_saddle_node_omega(double sigma, double r, double omega_near,
                                     const std::vector<double>& offsets) {
  return extrapolate(
      [&](double omega) {
        return saddle_node_factor({omega, r, sigma});
      },
      omega_near, offsets);
}

std::array<std::array<double, 2>, 2> map_jacobian_by_differences(const Oscillator& o,
                                                                 const PeriodOneOrbit& orbit,
                                                                 double h) {
  const auto map = [&](double t, double V) {
    const auto next = impact_map(o, {t, V}, 10 * orbit.T);
    if (!next) throw std::runtime_error("map_jacobian_by_differences: no impact");
    return *next;
  };
  const Impact tp = map(orbit.t0 + h, orbit.V), tm = map(orbit.t0 - h, orbit.V);
  const Impact Vp = map(orbit.t0, orbit.V + h), Vm = map(orbit.t0, orbit.V - h);
  return {{{(tp.t - tm.t) / (2 * h), (Vp.t - Vm.t) / (2 * h)},
           {(tp.V - tm.V) / (2 * h), (Vp.V - Vm.V) / (2 * h)}}};
}

}  // namespace impact::impact_oscillator
