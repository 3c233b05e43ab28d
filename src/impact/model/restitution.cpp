#include "impact/model/restitution.hpp"

#include <bit>
#include <cmath>

namespace impact {
namespace {

constexpr std::int64_t kSmallestNormal = std::int64_t{1} << 52;  // the bits of 2^-1022

// -COR v is -v bit for bit for v = +-m 2^-1074, with this processor's multiply. Round to nearest
// is symmetric, so for m > 0 one sign decides; at m = 0 the signs of the zeros decide.
bool maps_to_negative(double cor, std::int64_t m) {
  const double v = std::bit_cast<double>(m);
  const auto same = [](double a, double b) {
    return std::bit_cast<std::int64_t>(a) == std::bit_cast<std::int64_t>(b);
  };
  return same(-cor * v, -v) && (m > 0 || same(-cor * -v, v));
}

}  // namespace

// The set of such m is 0..M: the product is m units of 2^-1074 exactly when the exact COR m rounds
// to m, i.e. |1 - COR| m < 1/2 (or = 1/2 with m even), which holds for every m below a bound. So
// the bound is found from an estimate, 1 / (2 |1 - COR|), checked with the multiply itself at M and
// M + 1; bisection where the estimate misses (it is off by at most one or two units).
std::int64_t restitution_fixed_point(double cor) {
  if (!maps_to_negative(cor, 0)) return -1;
  const double estimate = 0.5 / std::fabs(1 - cor);  // inf for COR = 1
  std::int64_t low = estimate < static_cast<double>(kSmallestNormal - 1)
                         ? static_cast<std::int64_t>(estimate)
                         : kSmallestNormal - 1;
  const bool at_bound = low == kSmallestNormal - 1 || !maps_to_negative(cor, low + 1);
  if (maps_to_negative(cor, low) && at_bound) return low;
  // Invariant: m = low maps to -v, m = high does not (m = 2^52 is not a subnormal: excluded).
  low = 0;
  std::int64_t high = kSmallestNormal;
  while (high - low > 1) {
    const std::int64_t middle = low + (high - low) / 2;
    (maps_to_negative(cor, middle) ? low : high) = middle;
  }
  return low;
}

}  // namespace impact
