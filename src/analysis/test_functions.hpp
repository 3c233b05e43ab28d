// Test functions for distributions (the weak form of (2-1) in Section 4, the delta limit of
// Lemma 5): smooth and compactly supported.
#pragma once

namespace impact {

// The smooth bump psi(t) = exp(-1 / (1 - s^2)), s = (t - center) / radius, supported in
// |t - center| < radius, and its first two derivatives: the test function of the weak
// checks. Below q = 1 - s^2 = 1e-3, exp(-1/q) < e^-1000 underflows: the bump is 0 there.
struct Bump {
  double center = 0, radius = 1;
  double value(double t) const;
  double first(double t) const;
  double second(double t) const;
};

}  // namespace impact
