#include "analysis/error_analysis/error_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace impact::error_analysis {

double harmonic_flight_bound(double amplitude, double omega, double h, double span) {
  const double x = omega * h / (2 * std::numbers::pi);
  return std::fabs(amplitude) * h * h * std::fmin(2.0, omega * span) / (12 * (1 - x * x));
}

double smoothing_kick(double eps, double h, double d) {
  const double root = std::sqrt(eps);
  return d > 0 ? std::fmin(root, h * eps / (2 * d)) : root;
}

ImpactError direct_cor_impact(double V, double theta, double f, double h, double e) {
  const double rest = (1 - theta) * h;
  return {-rest * (e * V + f * rest / 2), -f * h * (1 - (1 + e) * theta)};
}

ImpactError direct_cor_impact_bound(double V, double f, double h, double e) {
  return {h * (e * V + std::fabs(f) * h / 2), std::fabs(f) * h};
}

double direct_scheme_rebound(double V, double theta, double f, double h) {
  return V * (1 - 2 * theta) + f * theta * (1 - theta) * h;
}

ImpactError moreau_jean_impact(double V, double sigma, double f, double h, double e) {
  const double dv = f * h * ((1 + e) * sigma - 1);
  return {(1 + e) * V * h * (sigma - 0.5) + h * dv / 2, dv};
}

double moreau_jean_sigma_bound(double V, double f, double h) {
  return 0.5 + std::fabs(f) * h / (8 * V);
}

ImpactError moreau_jean_impact_bound(double V, double f, double h, double e) {
  const double sigma = moreau_jean_sigma_bound(V, f, h);
  const double dv = std::fabs(f) * h * (1 + (1 + e) * sigma);
  return {(1 + e) * V * h * (sigma + 0.5) + h * dv / 2, dv};
}

double linear_crossing_error(double V, double theta, double f, double h) {
  return -f * theta * theta * h * h / (2 * (V + f * theta * h));
}

double linear_crossing_bound(double V, double f, double h) {
  return std::fabs(f) * h * h / (2 * (V - std::fmax(0.0, -f) * h));
}

double geometric_sum(double e, std::int64_t n) {
  if (n <= 0) return 0;
  if (e >= 1) return static_cast<double>(n);
  return e * -std::expm1(static_cast<double>(n) * std::log(e)) / (1 - e);
}

namespace {

// Sigma_k = sum_{n=1}^{k-1} S_e(n) = (e / (1 - e)) ((k - 1) - S_e(k - 1)); (k - 1) k / 2 for e = 1.
double sum_of_sums(double e, std::int64_t k) {
  const double m = static_cast<double>(k - 1);
  if (k <= 1) return 0;
  if (e >= 1) return m * (m + 1) / 2;
  return e / (1 - e) * (m - geometric_sum(e, k - 1));
}

// t_k and V_k of the exact bouncing solution under f = -g: t_1, V_1 given.
double impact_time(const ZenoData& d, std::int64_t k) {
  return d.t1 + 2 * d.V1 / d.g * geometric_sum(d.e, k - 1);
}
double impact_speed(const ZenoData& d, std::int64_t k) {
  return d.V1 * std::pow(d.e, static_cast<double>(k - 1));
}

}  // namespace

double timing_factor(double e, std::int64_t k) {
  return std::fmax(static_cast<double>(k - 1), 2 * sum_of_sums(e, k));
}

double delay_factor(double e, std::int64_t k) {
  return std::fmax(static_cast<double>(k), 2 * sum_of_sums(e, k));
}

double speed_bound(double g, double h, double e, std::int64_t k) {
  return g * h * geometric_sum(e, k);
}

std::int64_t max_impacts(double V1, double g, double h, double e) {
  if (e <= 0 || 2 * V1 <= g * h) return 1;
  if (e >= 1) return std::numeric_limits<std::int64_t>::max();
  return static_cast<std::int64_t>(std::floor(std::log(2 * V1 / (g * h)) / std::log(1 / e))) + 1;
}

double sup_bound(const ZenoData& d) {
  if (d.e <= 0) return 0;
  const double inf = std::numeric_limits<double>::infinity();
  const std::int64_t k_max = max_impacts(d.V1, d.g, d.h, d.e);
  double bound = 0;
  for (std::int64_t k = 1; k <= k_max; ++k) {
    const double B = delay_factor(d.e, k);
    if (impact_time(d, k) - d.h * B > d.T) return bound;
    // e = 1: past the impact where the speed bound reaches V_1 - g h / 2 the scheme may rest.
    if (d.e >= 1 && speed_bound(d.g, d.h, d.e, k) >= d.V1 - d.g * d.h / 2) return inf;
    // Near impact k both are between the floor and V_k^2 / (2 g), the apex of the flight before;
    // in flight k, below its apex (e V_k)^2 / (2 g).
    const double V = impact_speed(d, k);
    bound = std::fmax(bound, std::fmin(V * d.h * B, V * V / (2 * d.g)));
    if (k < k_max)
      bound = std::fmax(bound, std::fmin(d.h * d.e * V * (2 * geometric_sum(d.e, k) + B) +
                                             d.g * d.h * d.h * B * B / 2,
                                         d.e * d.e * V * V / (2 * d.g)));
  }
  const double tail = 0.5 + geometric_sum(d.e, k_max);
  return std::fmax(bound, d.g * d.h * d.h * tail * tail / 2);
}

double rest_bound(const ZenoData& d) {
  const std::int64_t k = max_impacts(d.V1, d.g, d.h, d.e);
  return d.h * std::fmax(static_cast<double>(k),
                         2 * sum_of_sums(d.e, k) + (1 + 2 * geometric_sum(d.e, k)) / (1 - d.e));
}

double max_k_e_power(double e) {
  if (e <= 0) return 1;
  if (e >= 1) return std::numeric_limits<double>::infinity();
  // max over x > 0 of x e^(x - 1) is at x = 1 / ln(1/e): 1 / (exp(1) e ln(1/e)).
  return std::fmax(1.0, 1 / (std::numbers::e * e * std::log(1 / e)));
}

double moreau_jean_sup_conjecture(const ZenoData& d) {
  if (d.e >= 1) return std::numeric_limits<double>::infinity();
  const double first = moreau_jean_impact_bound(d.V1, -d.g, d.h, d.e).du;
  if (d.e <= 0) return first;
  const double later = d.V1 * d.h * (1 + d.e) * (1 + 1 / d.e) *
                       std::fmax(1.0, 2 * d.e / (1 - d.e)) * max_k_e_power(d.e);
  return std::fmin(first + later, d.V1 * d.V1 / (2 * d.g) + (1 + d.e) * d.V1 * d.h);
}

double no_cor_lower_bound(double V, double theta, double t_star, double t) {
  return 2 * std::fmin(theta, 1 - theta) * V * (t - t_star);
}

namespace {

// The largest |du + dv s + A (sin(phase + omega s) - sin(phase))| over s in [0, span]: at the ends
// or where its derivative dv + A omega cos(phase + omega s) vanishes.
double flight_error_max(double du, double dv, double A, double omega, double phase, double span) {
  const auto error = [&](double s) {
    return du + dv * s + A * (std::sin(phase + omega * s) - std::sin(phase));
  };
  double largest = std::fmax(std::fabs(error(0)), std::fabs(error(span)));
  const double c = -dv / (A * omega);
  if (std::fabs(c) > 1) return largest;
  const double root = std::acos(c), period = 2 * std::numbers::pi;
  for (double base : {root, -root}) {
    // Every angle base + 2 pi k in [phase, phase + omega span].
    const double first = base + period * std::ceil((phase - base) / period);
    for (double angle = first; angle <= phase + omega * span; angle += period)
      largest = std::fmax(largest, std::fabs(error((angle - phase) / omega)));
  }
  return largest;
}

}  // namespace

double located_period1_constant(double g, double a, double omega, double e, double T) {
  const double period = 2 * std::numbers::pi / omega;
  const double psi = std::acos(std::numbers::pi * (1 - e) / (a / g * (1 + e)));
  const double v_in = g * period / (1 + e), f_star = -g + a * std::sin(psi), A = a / 12;
  // The first flight starts at t = 0 on the orbit, anchored there with no error.
  double t = psi / omega, du = 0, dv = 0;
  double largest = flight_error_max(du, dv, A, omega, 0, t);
  double du_end = A * std::sin(psi), dv_end = 0;
  for (; t < T; t += period) {
    du = -e * du_end;
    dv = -e * dv_end - (1 + e) * f_star * du_end / v_in;
    const double span = std::fmin(period, T - t);
    largest = std::fmax(largest, flight_error_max(du, dv, A, omega, psi, span));
    du_end = du + dv * period;  // sin(psi + 2 pi) - sin(psi) = 0
    dv_end = dv;
  }
  return largest;
}

}  // namespace impact::error_analysis
