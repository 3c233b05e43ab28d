#include "analysis/test_functions.hpp"

#include <cmath>

namespace impact {

double Bump::value(double t) const {
  const double s = (t - center) / radius, q = 1 - s * s;
  return q < 1e-3 ? 0.0 : std::exp(-1 / q);
}
double Bump::first(double t) const {
  const double s = (t - center) / radius, q = 1 - s * s;
  return q < 1e-3 ? 0.0 : std::exp(-1 / q) * (-2 * s / (q * q)) / radius;
}
double Bump::second(double t) const {
  const double s = (t - center) / radius, q = 1 - s * s;
  if (q < 1e-3) return 0.0;
  const double g1 = -2 * s / (q * q), g2 = -(2 + 6 * s * s) / (q * q * q);
  return std::exp(-1 / q) * (g1 * g1 + g2) / (radius * radius);
}

}  // namespace impact
