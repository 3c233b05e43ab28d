#include "analysis/fit.hpp"

#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace impact {

OrderFit fit_order(std::span<const double> h, std::span<const double> err) {
  if (h.size() != err.size()) throw std::invalid_argument("fit_order: h and err differ in size");
  std::vector<double> x, y;
  for (std::size_t i = 0; i < h.size(); ++i)
    if (err[i] > 0 && h[i] > 0) {
      x.push_back(std::log(h[i]));
      y.push_back(std::log(err[i]));
    }
  OrderFit fit;
  fit.points = x.size();
  if (x.size() < 2) return fit;
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(x.data(), 1, y.data(), 1, x.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  fit.order = c1;
  fit.log_constant = c0;
  if (x.size() > 2) fit.order_standard_error = std::sqrt(cov11);
  fit.h_min = std::exp(*std::min_element(x.begin(), x.end()));
  fit.h_max = std::exp(*std::max_element(x.begin(), x.end()));
  for (std::size_t i = 0; i < x.size(); ++i)
    fit.max_log_deviation = std::fmax(fit.max_log_deviation, std::fabs(y[i] - (c0 + c1 * x[i])));
  return fit;
}

std::vector<double> log_spaced(double h_max, double h_min, int n) {
  std::vector<double> h;
  for (int i = 0; i < n; ++i)
    h.push_back(n == 1 ? h_max : h_max * std::pow(h_min / h_max, static_cast<double>(i) / (n - 1)));
  return h;
}

// psi = exp(g(s)), g = -1 / (1 - s^2): g' = -2 s / (1 - s^2)^2, g'' = -(2 + 6 s^2) / (1 - s^2)^3,
// psi' = psi g' / r, psi'' = psi (g'^2 + g'') / r^2. Where 1 - s^2 < 1e-3, psi < e^-1000 underflows
// to 0 while the powers of 1 / (1 - s^2) could overflow, so 0 is returned there.

}  // namespace impact
