#include "analysis/lemma4/weak_solution.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "analysis/impact_times.hpp"
#include "analysis/quadrature.hpp"
#include "analysis/test_functions.hpp"

namespace impact::lemma4 {

namespace {

// (2-2), u >= phi: on a fine sampling and at the impact times.
double min_gap(const ExactSolution& x, const Model& model, double T,
               const std::vector<double>& kinks, int samples) {
  double gap = x.at(0).u - model.phi;
  for (int i = 0; i <= samples; ++i) gap = std::fmin(gap, x.at(T * i / samples).u - model.phi);
  for (double t : kinks) gap = std::fmin(gap, x.at(t).u - model.phi);
  return gap;
}

// (2-2), N >= 0 as a measure: the least impulse of a cell of a partition of (0, T] whose points
// include each impact time (so each atom falls into one cell).
double min_cell_impulse(const ExactSolution& x, double T, const std::vector<double>& kinks,
                        int cells) {
  std::vector<double> partition;
  for (int i = 0; i <= cells; ++i) partition.push_back(T * i / cells);
  partition.insert(partition.end(), kinks.begin(), kinks.end());
  std::sort(partition.begin(), partition.end());
  double least = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 1 < partition.size(); ++i)
    least = std::fmin(least, x.impulse(partition[i], partition[i + 1]));
  return least;
}

// The bumps psi of the distributional check: [0, T] covered at three widths, plus one centred on
// each of the first impacts.
std::vector<Bump> test_bumps(double T, const std::vector<double>& kinks) {
  std::vector<Bump> bumps;
  for (double radius : {T / 40, T / 10, T / 4})
    for (double c = radius * 1.01; c + radius * 1.01 < T; c += radius / 2)
      bumps.push_back({c, radius});
  for (std::size_t k = 0; k < kinks.size() && k < 8; ++k) {
    const double r = std::fmin(0.5, 0.99 * std::fmin(kinks[k], T - kinks[k]));
    if (r > 0) bumps.push_back({kinks[k], r});
  }
  return bumps;
}

}  // namespace

WeakSolutionCheck check_weak_solution(const ExactSolution& x, const Model& model, double T) {
  constexpr int kSamples = 100000;
  const std::vector<double> kinks = impact_times(x, T);
  WeakSolutionCheck check;
  check.min_gap = min_gap(x, model, T, kinks, kSamples);
  check.min_cell_impulse = min_cell_impulse(x, T, kinks, kSamples / 10);
  check.total_impulse = x.impulse(0, T);

  // (2-2), N (u - phi) = 0: int_(0,T] (u - phi) dI with I(t) = impulse(0, t) the cumulative
  // impulse, by parts for the continuous u: (u(T) - phi) I(T) - int_0^T I u' dt.
  // Each piece is a polynomial (u, v, I between impacts) times a smooth bump: the 21-point rule
  // reaches the round-off level with few subdivisions.
  Quadrature quad;
  const Quadrature::Rule rule{1e-13, 1e-12, GSL_INTEG_GAUSS21};
  const auto cumulative = [&](double t) { return x.impulse(0, t); };
  check.complementarity = (x.at(T).u - model.phi) * check.total_impulse -
                          quad.integrate([&](double t) { return cumulative(t) * x.at(t).v; }, 0, T,
                                         kinks, rule, "weak solution check");

  // (2-1) in the sense of distributions: int u psi'' = int psi dN + f int psi, where
  // int psi dN = -int psi' I dt (psi vanishes at the ends of its support).
  const std::vector<Bump> bumps = test_bumps(T, kinks);
  for (const Bump& psi : bumps) {
    const double a = psi.center - psi.radius, b = psi.center + psi.radius;
    const double u_psi2 = quad.integrate([&](double t) { return x.at(t).u * psi.second(t); }, a, b,
                                         kinks, rule, "weak solution check");
    const double psi_dN = -quad.integrate([&](double t) { return psi.first(t) * cumulative(t); }, a,
                                          b, kinks, rule, "weak solution check");
    const double f_psi = model.f * quad.integrate([&](double t) { return psi.value(t); }, a, b, {},
                                                  rule, "weak solution check");
    check.max_weak_residual =
        std::fmax(check.max_weak_residual, std::fabs(u_psi2 - psi_dN - f_psi));
    check.max_weak_scale = std::fmax(check.max_weak_scale, std::fabs(u_psi2));
  }
  check.test_functions = static_cast<int>(bumps.size());
  return check;
}

}  // namespace impact::lemma4
