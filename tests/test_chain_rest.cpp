// The two-mass chain's lower mass at rest on the floor (chain_rest.hpp): an accumulation of impacts
// cut off into a rest, the lift-off where the upper mass pulls it up, COR 0, and Moreau-Jean
// against the reference through rests.
#include <Eigen/Core>
#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "analysis/fit.hpp"
#include "chain_support.hpp"
#include "check_near.hpp"
#include "impact/chain/chain.hpp"
#include "impact/chain/chain_moreau_jean.hpp"
#include "impact/chain/chain_reference.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/references/exact_march.hpp"

using namespace impact;
using impact::testing::max_position_error;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A light lower mass under a heavy upper one whose spring starts compressed by 0.5, dropped from
// x1 = 0.02 with COR 0.5: the compressed spring pushes the lower mass down (p = 260 per unit mass),
// its impacts accumulate within 0.04 s, and it rests while the upper mass oscillates about its
// equilibrium d* = m2 g / k = -0.196 with amplitude 0.3, which exceeds (m1 + m2) |g| / k = 0.216:
// the spring pulls the lower mass off at t ~ 0.34, and the cycle repeats.
Chain lifting_chain(std::optional<double> cor = 0.5) {
  return Chain{0.1, 1.0, 50.0, 1.0, -9.81, 0.0, cor};
}
ChainState compressed(double x1 = 0.02) {
  ChainState s;
  s.q << x1, x1 + 0.5;
  return s;
}

// The COR 0 scene: the spring at rest 1 above the floor.
ChainState dropped_chain() {
  ChainState s;
  s.q << 1.0, 2.0;
  return s;
}

// The lift-off of a rest begun in the state s0 (x1 = phi, x1' = 0), independently of the
// reference's search: N = Nbar - k R cos(w2 tau - alpha) with Nbar = -(m1 + m2) g, reaching 0
// decreasing (sin(w2 tau - alpha) < 0) at w2 tau - alpha = -acos(Nbar / (k R)) mod 2 pi.
double closed_form_lift(const Chain& chain, const ChainState& s0, double t0) {
  const double w2 = std::sqrt(chain.k / chain.m2), d_star = chain.m2 * chain.g / chain.k;
  const double d0 = s0.q(1) - s0.q(0) - chain.ell, rate0 = s0.v(1);
  const double alpha = std::atan2(rate0 / w2, d0 - d_star);
  const double R = std::hypot(d0 - d_star, rate0 / w2);
  const double mean = -(chain.m1 + chain.m2) * chain.g;
  double phase = alpha - std::acos(mean / (chain.k * R));  // w2 tau, mod 2 pi
  while (phase < 0) phase += 2 * std::numbers::pi;
  return t0 + phase / w2;
}

}  // namespace

TEST_CASE("chain: accumulated impacts end in a rest that the upper mass lifts off",
          "[chain][property]") {
  const Chain chain = lifting_chain();
  const double T = 3;
  const ChainReference reference(chain, compressed(), {.t_end = T});
  const auto& rests = reference.rests();
  const auto& impacts = reference.impacts();
  REQUIRE(rests.size() >= 3);
  double fastest = 0;
  for (const ChainImpact& impact : impacts) fastest = std::fmax(fastest, -impact.v_before);
  for (std::size_t r = 0; r < rests.size(); ++r) {
    const ChainRest& rest = rests[r];
    INFO("rest " << r << " from " << rest.t << " to " << rest.lift);
    // It starts at a cut-off impact: plastic, slower than kChatterCutoff times the fastest, after
    // impacts whose speeds decay by e (to 1e-3 while the push p changes little).
    std::size_t i = 0;
    while (impacts[i].t < rest.t) ++i;
    REQUIRE(impacts[i].t == rest.t);
    CHECK(impacts[i].v_after == 0);
    CHECK(-impacts[i].v_before < kChatterCutoff * fastest);
    CHECK(impacts[i - 1].v_after == Approx(-0.5 * impacts[i - 1].v_before));
    CHECK(impacts[i - 1].v_after == Approx(-impacts[i].v_before).epsilon(1e-3));
    // The accumulation point from the first impact slower than 1e-4 times the fastest under its
    // push p, t_j + 2 e V_j / (p (1 - e)) (a constant p's geometric series): p changes by less
    // than 1e-3 of itself over that tail (|p'| <= (k / m1) w A ~ 6e3 over ~ 3e-6 s, against
    // p ~ 260), so the series is good to 1e-3 of the tail, and the cut-off's window is ~ 2e-10.
    std::size_t j = i;
    while (j > 0 && -impacts[j - 1].v_before < 1e-4 * fastest) --j;
    const double V = -impacts[j].v_before, d = [&] {
      const ChainState s = reference.at(impacts[j].t);
      return s.q(1) - s.q(0) - chain.ell;
    }();
    const double push = -(chain.g + chain.k / chain.m1 * d), tail = 2 * 0.5 * V / (push * 0.5);
    CHECK_NEAR(rest.t, impacts[j].t + tail, 1e-3 * tail);
    if (r + 1 < rests.size()) {
      REQUIRE(rest.lift < rests[r + 1].t);
    } else {
      CHECK(rest.lift == std::numeric_limits<double>::infinity());
      continue;
    }
    // During the rest N >= 0 (to its rounding, 4 eps of its terms), the lower mass on the floor.
    const ChainState s0 = reference.at(rest.t);
    const double n_scale = chain.m1 * std::fabs(chain.g) + chain.k * 1.0;  // |d| < 1
    double lowest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < 10000; ++j) {
      const double t = rest.t + (rest.lift - rest.t) * j / 10000;
      const ChainState s = reference.at(t);
      CHECK(s.q(0) == chain.phi);
      CHECK(s.v(0) == 0);
      lowest = std::fmin(lowest, reference.contact_force(t));
    }
    CHECK(lowest >= -4 * kEps * n_scale);
    // The lift-off against the closed form: a rounding delta N of N's terms (a few eps of
    // k |d| + (m1 + m2) |g|, both computations) moves the root by delta N / |N'|, and Brent's
    // bracket is 2 eps relative in t. Measured: lift-offs at 0.34352667749552662,
    // 1.3161040770454908, 2.247908747590186, within 1 ulp of the closed form (tolerances ~5e-15);
    // the rests start 1.9e-10 .. 8e-10 before the series' accumulation points (Intel Xeon family 6
    // model 167).
    const double lift = closed_form_lift(chain, s0, rest.t);
    const double rate = chain.k * std::fabs(reference.at(rest.lift).v(1));  // |N'| at the lift
    const double tolerance = 16 * kEps * n_scale / rate + 4 * kEps * rest.lift;
    CHECK_NEAR(rest.lift, lift, tolerance);
    CHECK(rate > 0);
    // After the lift the lower mass flies: above the floor right after it.
    CHECK(reference.at(rest.lift + 1e-3).q(0) > chain.phi);
  }
}

TEST_CASE("chain: moreau_jean converges to the reference through rests and lift-offs",
          "[chain][property]") {
  // The rest scene over T = 1: an accumulation, a rest, a lift-off at 0.34, a second accumulation
  // and rest. As in test_chain.cpp the error at each h is the mean over 8 drop heights 0.02, 0.021,
  // .., 0.027 (the impacts' positions in their steps), 30 values of h fitted together; asserted as
  // there. Measured: order 1.006 +- 0.013, error 2.9e-3 at h = 1e-3 .. 2.8e-5 at 1e-5 (Intel Xeon
  // family 6 model 167).
  constexpr int kHeights = 8;
  const std::vector<double> hs = log_spaced(1e-3, 1e-5, 30);
  std::vector<double> errors;
  for (const double h : hs) {
    double sum = 0;
    for (int j = 0; j < kHeights; ++j)
      sum += max_position_error(lifting_chain(), compressed(0.02 + 0.001 * j), h, 1.0);
    errors.push_back(sum / kHeights);
  }
  const OrderFit fit = fit_order(hs, errors);
  INFO("order " << fit.order << " +- " << fit.order_standard_error << ", error " << errors.front()
                << " .. " << errors.back());
  CHECK(fit.order >= 0.9);
  CHECK(fit.order_standard_error <= 0.05);
}

TEST_CASE("chain: during a rest the upper mass and the spring keep their energy",
          "[chain][property]") {
  // At rest x1 = phi is fixed, so E of chain.hpp is the upper mass's energy plus the spring's
  // (plus the constant -m1 g phi): conserved by the closed form up to rounding, each sample being
  // computed from the rest's start, a few eps of E's terms. Measured: 7.1e-15 over 4 rests, terms
  // up to 10.9 (Intel Xeon family 6 model 167), against 1.9e-14.
  const Chain chain = lifting_chain();
  const ChainReference reference(chain, compressed(), {.t_end = 3});
  double drift = 0, terms = 0;
  for (const ChainRest& rest : reference.rests()) {
    const double end = std::fmin(rest.lift, 3.0);
    const double e0 = chain_energy(chain, reference.at(rest.t));
    for (int j = 0; j <= 10000; ++j) {
      const ChainState s = reference.at(rest.t + (end - rest.t) * j / 10000);
      const double stretch = s.q(1) - s.q(0) - chain.ell;
      terms = std::fmax(terms, chain.m2 * s.v(1) * s.v(1) / 2 + chain.k * stretch * stretch / 2 +
                                   std::fabs(chain.g) * chain.m2 * std::fabs(s.q(1)));
      drift = std::fmax(drift, std::fabs(chain_energy(chain, s) - e0));
    }
  }
  INFO("drift " << drift << " terms " << terms);
  CHECK(drift <= 8 * kEps * terms);
}

TEST_CASE("chain: with COR 0 the lower mass sticks or leaves at once", "[chain][property]") {
  // Dropped with the spring at rest, both masses fall together and the first impact finds
  // N = -m1 g > 0: a rest, which the upper mass's rebound ends (amplitude R = 0.22 about d*,
  // k R = 45 > (m1 + m2) |g| = 14.7); later impacts find the spring either way (N of both signs).
  const Chain chain{1.0, 0.5, 200.0, 1.0, -9.81, 0.0, 0.0};
  const double T = 3;
  const ChainReference reference(chain, dropped_chain(), {.t_end = T});
  const auto& rests = reference.rests();
  REQUIRE(reference.impacts().size() >= 5);
  std::size_t rested = 0, left = 0;
  for (const ChainImpact& impact : reference.impacts()) {
    CHECK(impact.v_after == 0);
    CHECK(impact.v_before < 0);
    const ChainState s = reference.at(impact.t);
    const double push = -(chain.m1 * chain.g + chain.k * (s.q(1) - s.q(0) - chain.ell));
    const bool rests_here = std::any_of(rests.begin(), rests.end(),
                                        [&](const ChainRest& r) { return r.t == impact.t; });
    INFO("impact at " << impact.t << ", N " << push);
    CHECK(rests_here == (push >= 0));
    if (rests_here) {
      ++rested;
    } else {
      ++left;  // on the floor only at the instant: above it right after
      CHECK(reference.at(impact.t + 1e-6).q(0) > chain.phi);
    }
  }
  CHECK(rested >= 5);
  CHECK(left >= 1);
  for (const ChainRest& rest : rests) {
    if (rest.lift > T) continue;
    const ChainState s0 = reference.at(rest.t);
    const double rate = chain.k * std::fabs(reference.at(rest.lift).v(1));
    const double n_scale = chain.m1 * std::fabs(chain.g) + chain.k * 1.0;
    CHECK_NEAR(rest.lift, closed_form_lift(chain, s0, rest.t),
               16 * kEps * n_scale / rate + 4 * kEps * rest.lift);
  }
}

TEST_CASE("chain: a lower mass starting on the floor with zero speed rests or leaves",
          "[chain][property]") {
  const Chain chain{1.0, 0.5, 200.0, 1.0, -9.81, 0.0, 0.8};
  ChainState start;
  start.q << 0.0, 1.0;  // the spring at rest: N = -m1 g > 0, a rest from t = 0
  const ChainReference resting(chain, start, {.t_end = 1});
  REQUIRE(!resting.rests().empty());
  CHECK(resting.rests().front().t == 0);
  CHECK(resting.contact_force(0) == -chain.m1 * chain.g);
  start.q(1) = 1.2;  // stretched by 0.2: N = 9.81 - 40 < 0, it leaves at once
  const ChainReference leaving(chain, start, {.t_end = 1});
  CHECK((leaving.rests().empty() || leaving.rests().front().t > 0));
  CHECK(leaving.at(1e-6).q(0) > chain.phi);
  CHECK(leaving.contact_force(0) == 0);
}

TEST_CASE("chain: the reference keeps the impulse identity through rests", "[chain][property]") {
  // h sum N^l = (m1 x1' + m2 x2')(T) - (same at 0) - (m1 + m2) g T, the rests' impulse included
  // (their integral of N, from the upper mass's momentum; the identity then checks the sum of the
  // pieces over the grid's steps). Both scenes rest (the tests above).
  for (const auto& [chain, initial] :
       {std::pair{lifting_chain(), compressed()},
        std::pair{Chain{1.0, 0.5, 200.0, 1.0, -9.81, 0.0, 0.0}, dropped_chain()}}) {
    const double h = 1e-3;
    const Grid grid = Grid::covering(3, h);
    const auto momentum = [&](const ChainState& s) {
      return chain.m1 * s.v(0) + chain.m2 * s.v(1);
    };
    double impulse = 0;
    ChainState last;
    ChainReferenceStepper stepper(chain, h, {.t_end = grid.end()});
    simulate(stepper, initial, grid, [&](std::int64_t, const ChainState& s, const StepInfo& i) {
      impulse += h * i.contact_force;
      last = s;
    });
    const double expected =
        momentum(last) - momentum(initial) - (chain.m1 + chain.m2) * chain.g * grid.end();
    INFO("impulse " << impulse << " momentum change " << expected);
    CHECK(impulse > 10);
    CHECK(impulse == Approx(expected).epsilon(1e-12));
  }
}
