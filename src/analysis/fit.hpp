// Observed orders of convergence: least-squares fits on log-log axes (GSL), one for every study.
#pragma once

#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace impact {

// Least-squares fit log err = log C + p log h over the points with err > 0.
struct OrderFit {
  double order = std::numeric_limits<double>::quiet_NaN();
  double log_constant = std::numeric_limits<double>::quiet_NaN();
  double h_min = 0, h_max = 0;
  std::size_t points = 0;
  double max_log_deviation = 0;  // max |log err - fit| over the points: how straight the line is
  // The standard error of the order from the scatter of the points about the line (GSL's
  // covariance of the slope; NaN with fewer than three points): how well the points fix it.
  double order_standard_error = std::numeric_limits<double>::quiet_NaN();
};
OrderFit fit_order(std::span<const double> h, std::span<const double> err);

// n log-spaced values from h_max down to h_min.
std::vector<double> log_spaced(double h_max, double h_min, int n);

}  // namespace impact
