#include "impact/steppers/direct_located.hpp"

#include <cmath>

namespace impact {

FloorArrival floor_arrival(const State& gap_state, double f) {
  const double g = std::fmax(gap_state.u, 0.0), v = gap_state.v;
  const double discriminant = v * v - 2 * f * g;
  FloorArrival a;
  if (v < 0) {
    if (discriminant < 0) return a;  // f > 0 turns the particle back above the floor
    a.speed = std::sqrt(discriminant);
    a.tau = 2 * g / (a.speed - v);  // the smaller root, without cancellation
  } else {
    if (!(f < 0)) return a;  // moving up or at rest, never pulled down
    a.speed = std::sqrt(discriminant);
    a.tau = (v + a.speed) / -f;
  }
  a.found = true;
  return a;
}

State bounce_from_floor(double w, double r, double f, double e) {
  if (!(r > 0)) return {0.0, w};  // at the impact instant: v is the post-impact velocity
  if (f >= 0) return {r * (w + r * f / 2), w + r * f};
  const double pull = -f;
  const auto flight = [&](double launch, double s) -> State {
    return {std::fmax(0.0, s * (launch - s * pull / 2)), launch - s * pull};
  };
  const double first = 2 * w / pull;  // the first flight's duration
  if (!(w > 0)) return {0.0, 0.0};
  if (r < first) return flight(w, r);
  if (e == 0) return {0.0, 0.0};  // plastic: at rest from the first return
  // k complete flights take S_k = first (1 - e^k) / (1 - e) (first k for e = 1).
  const auto elapsed = [&](double k) {
    return e < 1 ? first * (-std::expm1(k * std::log(e))) / (1 - e) : k * first;
  };
  double k;
  if (e < 1) {
    const double x = r * (1 - e) / first;
    if (x >= 1) return {0.0, 0.0};  // past the accumulation point: at rest
    k = std::floor(std::log1p(-x) / std::log(e));
  } else {
    k = std::floor(r / first);
  }
  // Rounding can put the count one off either way; the flights' own times decide.
  for (int fix = 0; fix < 4 && k > 1 && elapsed(k) > r; ++fix) k -= 1;
  for (int fix = 0; fix < 4 && elapsed(k + 1) <= r; ++fix) k += 1;
  const double launch = w * std::pow(e, k);
  const double since = std::fmin(std::fmax(r - elapsed(k), 0.0), 2 * launch / pull);
  return flight(launch, since);
}

State located_step(const State& gap_state, const State& free, double h, double f, double e) {
  const FloorArrival a = floor_arrival(gap_state, f);
  if (!a.found || a.tau > h) {
    // The step's parabola stays above the floor by rounding: where the free flight (the anchor's
    // closed form) ends above the floor the particle is there, else the impact is at t_{l+1}.
    if (free.u > 0) return free;
    return {0.0, -e * std::fmin(free.v, 0.0)};
  }
  return bounce_from_floor(e * a.speed, h - a.tau, f, e);
}

State located_step(const State& gap_state, const State& free, double t_l, double h, double f,
                   const ForceFunction& force, double e) {
  const FloorArrival a = floor_arrival(gap_state, f);
  if (!a.found || a.tau > h) return located_step(gap_state, free, h, f, e);
  const double t_impact = t_l + a.tau;
  const double v_before = std::fmin(gap_state.v + force.integral(t_l, t_impact), 0.0);
  const double rest = h - a.tau;
  const double f_rest = rest > 0 ? force.integral(t_impact, t_l + h) / rest : f;
  return bounce_from_floor(-e * v_before, rest, f_rest, e);
}

}  // namespace impact
