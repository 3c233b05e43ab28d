#include "impact/chain/chain_rest.hpp"

#include <cmath>
#include <limits>

namespace impact {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// w^2 = k (1/m1 + 1/m2), the stretch's frequency in flight (chain_reference.hpp).
double flight_frequency(const Chain& chain) {
  return std::sqrt(chain.k * (1 / chain.m1 + 1 / chain.m2));
}

}  // namespace

ChainState chain_rest_at(const Chain& chain, const ChainState& s0, double tau) {
  const double w2 = std::sqrt(chain.k / chain.m2);
  const double rate0 = s0.v(1);
  // d(tau) - d0 - d0' tau, written with the acceleration a0 = g - w2^2 d0 at the rest's start so
  // that k -> 0 leaves the free fall g tau^2 / 2 without cancellation: (1 - cos x) / w2^2 =
  // 2 sin^2(x/2) / w2^2 -> tau^2 / 2.
  double bend = chain.g * tau * tau / 2, bend_rate = chain.g * tau;
  if (w2 > 0) {
    const double a0 = chain.g - w2 * w2 * chain_stretch(chain, s0);
    const double x = w2 * tau, half = std::sin(x / 2), sine = std::sin(x);
    const double versine = 2 * (half / w2) * (half / w2);  // (1 - cos x) / w2^2
    bend = a0 * versine + rate0 * (sine - x) / w2;
    bend_rate = a0 * sine / w2 - 2 * rate0 * half * half;
  }
  ChainState s;
  s.q << 0.0, s0.q(1) + rate0 * tau + bend;
  s.v << 0.0, rate0 + bend_rate;
  return s;
}

std::optional<Contact> chain_lift(const Chain& chain, double t0, const ChainState& s0,
                                  double horizon, long& budget) {
  // N, N' = -k d' and N'' = -k d'' = -k (g - w2^2 d) along the rest, as a gap for search_contact.
  struct RestForce {
    const Chain& chain;
    double t0;
    const ChainState& s0;
    State at(double t) const {
      const ChainState s = chain_rest_at(chain, s0, t - t0);
      return {chain_rest_force(chain, s), -chain.k * s.v(1)};
    }
    double force(double t) const {
      const ChainState s = chain_rest_at(chain, s0, t - t0);
      return -chain.k * (chain.g - chain.k / chain.m2 * chain_stretch(chain, s));
    }
  } path{chain, t0, s0};
  // d'' oscillates at w2 with the amplitude hypot(d''(0), w2 d'(0)): the bound on |N''|.
  const double w2 = std::sqrt(chain.k / chain.m2);
  const double bound =
      chain.k * std::hypot(chain.g - w2 * w2 * chain_stretch(chain, s0), w2 * s0.v(1));
  if (bound == 0) return std::nullopt;  // N is constant: the rest lasts
  double certified = t0, checked = t0;
  return search_contact(path, bound, certified, checked, horizon, budget);
}

double chain_departure(const Chain& chain, const ChainState& s) {
  const double k_m1 = chain.k / chain.m1, d = chain_stretch(chain, s), rate = s.v(1) - s.v(0);
  // gap'' = -N / m1, so that a lift-off's N <= 0 gives a >= 0 whatever the rounding.
  const double a = -chain_rest_force(chain, s) / chain.m1, j = k_m1 * rate;
  const double w = flight_frequency(chain);
  const double amplitude = w > 0 ? std::hypot(d, rate / w) : 0.0;
  const double C = k_m1 * w * amplitude, D = C * w;
  double stretch = 0;
  if (a > 0) stretch = C > 0 ? 1.5 * a / C : kInfinity;
  if (a >= 0 && j > 0) stretch = std::fmax(stretch, 2 * j / D);
  return stretch;
}

std::optional<double> chain_chatter_window(const Chain& chain, double e, double V,
                                           const ChainState& after) {
  if (!(e > 0 && e < 1 && V > 0)) return std::nullopt;
  const double k_m1 = chain.k / chain.m1, d = chain_stretch(chain, after);
  const double push = -(chain.g + k_m1 * d);
  if (!(push > 0)) return std::nullopt;
  const double W0 = chatter_trial_window(e, V, push);
  const double rho_trial = (1 + e) / 2;
  const double jumps = (1 + e) * V / (1 - rho_trial);
  const double w = flight_frequency(chain), rate = after.v(1) - after.v(0);
  const double rate_bound = (w > 0 ? w * std::hypot(d, rate / w) : 0.0) + jumps;
  const double spread = k_m1 * rate_bound * W0;
  const double p_min = push - spread, p_max = push + spread;
  if (!(p_min > 0 && e * std::sqrt(p_max / p_min) <= rho_trial)) return std::nullopt;
  return chatter_window_within(e, V, W0, p_min, p_max);
}

}  // namespace impact
