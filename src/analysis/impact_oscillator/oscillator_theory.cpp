#include "analysis/impact_oscillator/oscillator_theory.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>

#include "impact/format.hpp"

namespace impact::impact_oscillator {

namespace {

constexpr double kPi = std::numbers::pi;

struct Constants {
  double gamma, T, c_s, r_minus;
};

Constants constants(double omega, double r, int n) {
  const double T = 2 * kPi * n / omega;
  return {1 / (1 - omega * omega), T, (1 + r) * std::sin(T) / (1 - std::cos(T)), (1 - r) / omega};
}

// K of (O-3): the trace without its sigma/V term.
double trace_constant(double omega, double r, double T) {
  const double c2 = std::cos(T / 2) * std::cos(T / 2), s2 = 1 - c2;
  return (1 + r * r) * c2 + 2 * r * s2 - omega * omega * (1 + r) * (1 + r) * c2;
}

// The first sign change of f on a scan of `points` from `from` toward `to`, refined by GSL's Brent
// to 1e-14 relative; nullopt without one (points where f is not finite are skipped).
std::optional<double> first_crossing(const std::function<double(double)>& f, double from, double to,
                                     int points = 400) {
  double a = from, fa = f(from);
  for (int i = 1; i <= points; ++i) {
    const double b = from + (to - from) * i / points, fb = f(b);
    if (std::isfinite(fa) && std::isfinite(fb) && (fa < 0) != (fb < 0)) {
      gsl_function F{[](double x, void* p) { return (*static_cast<decltype(&f)>(p))(x); },
                     const_cast<std::function<double(double)>*>(&f)};
      const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> solver(
          gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
      double lo = std::fmin(a, b), hi = std::fmax(a, b);
      gsl_root_fsolver_set(solver.get(), &F, lo, hi);
      for (int it = 0; it < 200; ++it) {
        if (gsl_root_fsolver_iterate(solver.get()) != GSL_SUCCESS) break;
        lo = gsl_root_fsolver_x_lower(solver.get());
        hi = gsl_root_fsolver_x_upper(solver.get());
        if (gsl_root_test_interval(lo, hi, 0.0, 1e-14) == GSL_SUCCESS) break;
      }
      return (lo + hi) / 2;
    }
    a = b;
    fa = fb;
  }
  return std::nullopt;
}

}  // namespace

double Oscillator::period() const {
  return 2 * kPi / omega;
}
double Oscillator::gamma() const {
  return 1 / (1 - omega * omega);
}

LinearForce oscillator_force(double omega) {
  return {1.0, 0.0, 0.0, 0.0, -1.0, omega, kPi / 2};
}

Model oscillator_model(const Oscillator& o) {
  Model m;
  m.phi = o.phi();
  m.cor = o.r;
  return m;
}

std::string oscillator_expression(double omega) {
  return "-u - cos(" + round_trip(omega) + "*t)";
}

std::optional<PeriodOneOrbit> period_one_orbit(const Oscillator& o, int n, int branch) {
  const Constants k = constants(o.omega, o.r, n);
  if (!std::isfinite(k.gamma) || !std::isfinite(k.c_s)) return std::nullopt;
  const double a = k.c_s * k.c_s + k.r_minus * k.r_minus;
  const double disc = k.gamma * k.gamma * a - o.sigma * o.sigma * k.r_minus * k.r_minus;
  if (!(disc >= 0.0)) return std::nullopt;
  const double V = (-2 * k.c_s * o.sigma + branch * 2 * std::sqrt(disc)) / a;
  if (!(V > 0.0)) return std::nullopt;
  PeriodOneOrbit orbit;
  orbit.V = V;
  orbit.T = k.T;
  orbit.c_s = k.c_s;
  orbit.r_minus = k.r_minus;
  orbit.gamma = k.gamma;
  const double cosine = (o.sigma + k.c_s * V / 2) / k.gamma, sine = -k.r_minus * V / (2 * k.gamma);
  orbit.phase = std::atan2(sine, cosine);
  if (orbit.phase < 0) orbit.phase += 2 * kPi;
  orbit.t0 = orbit.phase / o.omega;
  orbit.acos_phase = std::acos(std::fmax(-1.0, std::fmin(1.0, cosine)));
  return orbit;
}

double orbit_trace(const Oscillator& o, double V, int n) {
  const double T = 2 * kPi * n / o.omega;
  return trace_constant(o.omega, o.r, T) -
         o.omega * o.omega * (1 + o.r) * o.sigma * std::sin(T) / V;
}

std::array<std::array<double, 2>, 2> orbit_jacobian(const Oscillator& o,
                                                    const PeriodOneOrbit& orbit) {
  const double g = orbit.gamma, w = o.omega, T = orbit.T, V = orbit.V;
  const double s = std::sin(orbit.phase), c = std::cos(orbit.phase);
  const double Gt = g * w * s * (std::cos(T) - 1) + g * w * w * c * std::sin(T);
  const double GV = -o.r * std::sin(T);
  const double Ht = -g * w * s * std::sin(T) + g * w * w * c * (std::cos(T) - 1);
  const double HV = -o.r * std::cos(T);
  const double Htau = c - o.sigma;
  return {{{1 - Gt / V, -GV / V}, {Ht - Htau * Gt / V, HV - Htau * GV / V}}};
}

double leading_multiplier(double trace, double r) {
  // lambda^2 - Tr lambda + r^2 = 0.
  const double disc = trace * trace / 4 - r * r;
  if (disc <= 0.0) return r;  // a complex pair of modulus sqrt(det) = r
  return std::fabs(trace) / 2 + std::sqrt(disc);
}

double saddle_node_sigma(double omega, double r, int n) {
  const Constants k = constants(omega, r, n);
  const double bound =
      std::fabs(k.gamma) * std::sqrt(1 + (k.c_s / k.r_minus) * (k.c_s / k.r_minus));
  // At the double root V = -2 c_s sigma/(c_s^2 + r_-^2) > 0: sigma has the sign of -c_s.
  return k.c_s > 0 ? -bound : bound;
}

double period_doubling_sigma(double omega, double r, int n) {
  const Constants k = constants(omega, r, n);
  const double m =
      (trace_constant(omega, r, k.T) + (1 + r * r)) / (omega * omega * (1 + r) * std::sin(k.T));
  const double V =
      std::fabs(k.gamma) / std::sqrt((m + k.c_s / 2) * (m + k.c_s / 2) + k.r_minus * k.r_minus / 4);
  return m * V;
}

double grazing_sigma(double omega) {
  return std::fabs(1 / (1 - omega * omega));
}

std::optional<double> saddle_node_omega(double sigma, double r, double lo, double hi, int n) {
  return first_crossing(
      [&](double omega) {
        const Constants k = constants(omega, r, n);
        return k.gamma * k.gamma * (k.c_s * k.c_s + k.r_minus * k.r_minus) -
               sigma * sigma * k.r_minus * k.r_minus;
      },
      lo, hi);
}

std::optional<double> period_doubling_omega(double sigma, double r, double lo, double hi, int n) {
  return first_crossing(
      [&](double omega) {
        const Oscillator o{omega, r, sigma};
        const auto orbit = period_one_orbit(o, n);
        if (!orbit) return std::numeric_limits<double>::quiet_NaN();
        return orbit_trace(o, orbit->V, n) + (1 + r * r);
      },
      lo, hi);
}

double grazing_curvature(double omega) {
  return 1 + grazing_sigma(omega);
}

double grazing_first_speed(double omega, double delta) {
  return omega * std::sqrt(delta * (2 * grazing_sigma(omega) - delta));
}

double accumulation_time(double v0, double a, double r) {
  return 2 * v0 / (a * (1 - r));
}

double accumulation_time_first_order(double v0, double a0, double a1, double r) {
  return accumulation_time(v0, a0, r) * (1 - 2.0 / 3.0 * a1 * v0 / (a0 * a0 * (1 - r)));
}

double lift_off_angle(double phi) {
  return std::acos(-phi);
}

}  // namespace impact::impact_oscillator
