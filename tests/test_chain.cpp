// The two-mass chain (chain.hpp): its event-driven reference, Moreau-Jean on two degrees of
// freedom, and the limit k = 0 in which the lower mass is the paper's particle.
#include <Eigen/Core>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

#include "analysis/fit.hpp"
#include "chain_support.hpp"
#include "impact/chain/chain.hpp"
#include "impact/chain/chain_moreau_jean.hpp"
#include "impact/chain/chain_reference.hpp"
#include "impact/loop/simulate.hpp"
#include "impact/references/exact.hpp"
#include "impact/steppers/moreau_jean.hpp"

using namespace impact;
using impact::testing::max_position_error;

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

// A bouncing chain: the spring at rest 1 above a floor at 0, dropped from rest under g = -9.81.
// The stretch's frequency is w = sqrt(20 (1 + 2)) ~ 7.7 rad/s; its amplitude (~0.2) stays below
// the rest length, so the upper mass stays above the lower one (checked).
Chain bouncing_chain(std::optional<double> cor = std::nullopt) {
  return Chain{1.0, 0.5, 200.0, 1.0, -9.81, 0.0, cor};
}
ChainState dropped(double x1 = 1.0) {
  ChainState s;
  s.q << x1, x1 + 1.0;
  return s;
}

}  // namespace

TEST_CASE("chain: the reference conserves the energy to rounding over 95 elastic impacts",
          "[chain][property]") {
  const Chain chain = bouncing_chain();
  const double T = 50;
  const ChainReference reference(chain, dropped(), {.t_end = T});
  const double e0 = chain_energy(chain, dropped());
  const auto impacts = static_cast<double>(reference.impacts().size());
  REQUIRE(impacts >= 90);
  double drift = 0, closest = std::numeric_limits<double>::infinity();
  for (const ChainImpact& impact : reference.impacts()) {
    drift = std::fmax(drift, std::fabs(chain_energy(chain, reference.at(impact.t)) - e0));
    CHECK(impact.v_after == -impact.v_before);
  }
  for (int i = 0; i <= 100000; ++i) {
    const ChainState s = reference.at(T * i / 100000);
    drift = std::fmax(drift, std::fabs(chain_energy(chain, s) - e0));
    closest = std::fmin(closest, s.q(1) - s.q(0));
    CHECK(s.q(0) >= chain.phi);
  }
  // Each flight is closed form from the state after an impact, so only the impacts carry rounding
  // forward: the state at the root holds a few ulp of each term of E (|terms| <= E0 here), taken as
  // 4 eps E0 per impact and summed without cancellation. Measured 1.5e-13 (Intel Xeon family 6
  // model 167), against 1.6e-12.
  INFO("drift " << drift << " over " << impacts << " impacts");
  CHECK(drift <= impacts * 4 * kEps * e0);
  CHECK(closest > 0.5);  // the upper mass stays above the lower one (chain.hpp's assumption)
}

TEST_CASE("chain: moreau_jean with theta = 1/2 keeps the elastic chain's energy to rounding",
          "[chain][property]") {
  // In flight the midpoint rule conserves the energy of a linear system with a constant force
  // exactly; at an elastic contact step the law sets x1'^{l+1} = -x1'^l, so the lower mass does
  // not move ((x1'^{l+1} + x1'^l) / 2 = 0) and the impulse does no work. What remains is rounding:
  // each step rounds each of the four terms of E at most once, 4 eps E0 per step, summed without
  // cancellation. Measured: 3.5e-12, 7.8e-11, 1.8e-11 at h = 1e-2, 1e-3, 1e-4 over 95 impacts
  // (Intel Xeon family 6 model 167), against 2.2e-11, 8.7e-10 and 8.7e-9.
  const Chain chain = bouncing_chain();
  const double e0 = chain_energy(chain, dropped());
  for (const double h : {1e-2, 1e-3, 1e-4}) {
    const Grid grid = Grid::covering(50, h);
    ChainMoreauJean stepper(chain, h, MoreauJeanParams{});
    double drift = 0;
    std::int64_t contacts = 0;
    simulate(stepper, dropped(), grid, [&](std::int64_t, const ChainState& s, const StepInfo& i) {
      drift = std::fmax(drift, std::fabs(chain_energy(chain, s) - e0));
      contacts += i.contact_force > 0;
    });
    INFO("h " << h << " drift " << drift << " contact steps " << contacts);
    CHECK(contacts >= 90);
    CHECK(drift <= static_cast<double>(grid.steps) * 4 * kEps * e0);
  }
}

TEST_CASE("chain: moreau_jean converges to the reference at first order", "[chain][property]") {
  // The error of a run is its largest position error over the grid. Each impact is taken up to a
  // step early or late, an error (1 - theta) h |jump| with theta the impact's position in its
  // step, which jumps erratically with h (as for the one particle, test_convergence.cpp): so the
  // error at each h is the mean over 8 drop heights 1, 1.01, .., 1.07 (8 values of theta), and 30
  // values of h are fitted together; the order is asserted >= 0.9 with a standard error <= 0.05
  // (two of them below 1). COR 0.8 over T = 2 (5 impacts): order 1.01 +- 0.03. Elastic, over
  // T = 0.5 (one impact, the spring ringing after it): 0.98 +- 0.04. Over longer elastic runs the
  // error grows fast with T and the fit over these h is not yet asymptotic: order 0.89 at T = 0.75,
  // 0.65 at T = 1.5, 0.41 at T = 2 (the sequence of impacts is sensitive to their timing; not
  // studied further), while COR 0.8 stays at 0.98-1.01 for T = 0.5 .. 2.
  constexpr int kHeights = 8;
  for (const auto& [cor, T] :
       {std::pair{std::optional<double>{}, 0.5}, std::pair{std::optional<double>{0.8}, 2.0}}) {
    const std::vector<double> hs = log_spaced(1e-2, 1e-4, 30);
    std::vector<double> errors;
    for (const double h : hs) {
      double sum = 0;
      for (int j = 0; j < kHeights; ++j)
        sum += max_position_error(bouncing_chain(cor), dropped(1 + 0.01 * j), h, T);
      errors.push_back(sum / kHeights);
    }
    const OrderFit fit = fit_order(hs, errors);
    INFO("cor " << cor.value_or(1) << ", T = " << T << ": order " << fit.order << " +- "
                << fit.order_standard_error << ", error " << errors.front() << " .. "
                << errors.back());
    CHECK(fit.order >= 0.9);
    CHECK(fit.order_standard_error <= 0.05);
  }
}

TEST_CASE("chain: with k = 0 the lower mass is the paper's particle", "[chain][property]") {
  // Uncoupled, the lower mass obeys (2-1)-(2-4) with f = g: the reference against ExactSolution
  // (closed form) and Moreau-Jean against the one particle's MoreauJean, through the same law.
  for (const auto cor : {std::optional<double>{}, std::optional<double>{0.9}}) {
    const Chain chain{1.0, 0.3, 0.0, 1.0, -9.81, 0.25, cor};
    ChainState initial;
    initial.q << 1.25, 3.0;
    initial.v << -0.5, 2.0;
    const Model model{.phi = 0.25, .f = -9.81, .cor = cor};
    const double T = 5;  // before the Zeno time with COR 0.9 (8.4)
    const ExactSolution exact(model, State{1.25, -0.5});
    const ChainReference reference(chain, initial, {.t_end = T});
    REQUIRE(reference.impacts().size() >= 4);
    CHECK(reference.impacts().size() == static_cast<std::size_t>(exact.impacts_until(T)));
    double gap = 0, speed = 0;
    for (int i = 0; i <= 100000; ++i) {
      const double t = T * i / 100000;
      const State u = exact.at(t);
      const ChainState s = reference.at(t);
      gap = std::fmax(gap, std::fabs(s.q(0) - u.u));
      speed = std::fmax(speed, std::fabs(s.v(0) - u.v));
      // The upper mass flies freely.
      CHECK(s.q(1) == Approx(3.0 + 2.0 * t - 9.81 * t * t / 2).margin(1e-13));
    }
    // Both are closed forms; the reference's impact times come from Brent's root to 2 eps
    // relative, the exact ones from the parabola's root: a few ulp of t (~5) times the speed (~10)
    // per impact, and a sample falling between the two times of one impact sees the whole jump.
    // Measured: 5.5e-15 in x1, 9.8e-15 in x1' (Intel Xeon family 6 model 167).
    INFO("cor " << cor.value_or(1) << ": |x1 - u| <= " << gap << ", |x1' - v| <= " << speed);
    CHECK(gap <= 1e-13);
    CHECK(speed <= 1e-13);

    // Moreau-Jean: with m1 = 1 and k = 0, W = M and the chain's step is the one particle's, bit
    // for bit.
    const double h = 1e-3;
    const Grid grid = Grid::covering(T, h);
    ChainMoreauJean chain_stepper(chain, h, MoreauJeanParams{});
    MoreauJean particle(model, h, MoreauJeanParams{});
    std::vector<State> particle_states;
    std::vector<double> particle_forces;
    simulate(particle, State{1.25, -0.5}, grid,
             [&](std::int64_t, const State& s, const StepInfo& i) {
               particle_states.push_back(s);
               particle_forces.push_back(i.contact_force);
             });
    std::int64_t differ = 0, contacts = 0;
    simulate(chain_stepper, initial, grid,
             [&](std::int64_t l, const ChainState& s, const StepInfo& i) {
               const auto k = static_cast<std::size_t>(l);
               differ += s.q(0) != particle_states[k].u || s.v(0) != particle_states[k].v;
               contacts += i.contact_force > 0;
               CHECK(i.contact_force == Approx(particle_forces[k]).epsilon(1e-14));
             });
    CHECK(differ == 0);
    CHECK(contacts >= 4);
  }
}

TEST_CASE("chain: both solvers keep the impulse identity", "[chain][property]") {
  // The spring is internal: h sum N^l = (m1 x1' + m2 x2')(T) - (same at 0) - (m1 + m2) g T.
  const Chain chain = bouncing_chain(0.8);
  const double h = 1e-3;
  const Grid grid = Grid::covering(2, h);
  const auto momentum = [&](const ChainState& s) { return chain.m1 * s.v(0) + chain.m2 * s.v(1); };
  const auto check = [&](auto stepper) {
    double impulse = 0;
    ChainState last;
    simulate(stepper, dropped(), grid, [&](std::int64_t, const ChainState& s, const StepInfo& i) {
      impulse += h * i.contact_force;
      last = s;
    });
    const double expected =
        momentum(last) - momentum(dropped()) - (chain.m1 + chain.m2) * chain.g * grid.end();
    INFO("impulse " << impulse << " momentum change " << expected);
    CHECK(impulse > 10);
    CHECK(impulse == Approx(expected).epsilon(1e-12));
  };
  check(ChainMoreauJean(chain, h, MoreauJeanParams{}));
  check(ChainReferenceStepper(chain, h, {.t_end = grid.end()}));
}

TEST_CASE("chain: bad parameters and non-finite values are refused or reported",
          "[chain][bad-input]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Chain good = bouncing_chain();
  std::vector<Chain> bad(9, good);
  bad[0].m1 = 0;
  bad[1].m2 = -1;
  bad[2].k = -1;
  bad[3].k = nan;
  bad[4].ell = inf;
  bad[5].g = nan;
  bad[6].phi = -inf;
  bad[7].cor = 1.5;
  bad[8].cor = nan;
  for (const Chain& chain : bad) {
    CHECK_THROWS_AS(check_chain(chain), std::invalid_argument);
    CHECK_THROWS_AS(ChainMoreauJean(chain, 1e-3, MoreauJeanParams{}), std::invalid_argument);
    CHECK_THROWS_AS(ChainReference(chain, dropped(), {.t_end = 1}), std::invalid_argument);
    CHECK_THROWS_AS(ChainReferenceStepper(chain, 1e-3, {.t_end = 1}), std::invalid_argument);
  }
  CHECK_THROWS_WITH(check_chain(bad[0]), Catch::Contains("m1 = 0") && Catch::Contains("> 0"));
  for (const double h : {0.0, -1e-3, nan, inf}) {
    CHECK_THROWS_AS(ChainMoreauJean(good, h, MoreauJeanParams{}), std::invalid_argument);
    CHECK_THROWS_AS(ChainReferenceStepper(good, h, {.t_end = 1}), std::invalid_argument);
  }
  for (const double theta : {-0.1, 1.5, nan})
    CHECK_THROWS_AS(ChainMoreauJean(good, 1e-3, MoreauJeanParams{theta}), std::invalid_argument);
  // The reference: a start below the floor or not finite, and t_end.
  CHECK_THROWS_WITH(ChainReference(good, dropped(-0.1), {.t_end = 1}),
                    Catch::Contains("x1 = -0.1"));
  ChainState not_finite = dropped();
  not_finite.v(1) = nan;
  CHECK_THROWS_WITH(ChainReference(good, not_finite, {.t_end = 1}), Catch::Contains("v2 = nan"));
  CHECK_THROWS_AS(ChainReference(good, dropped(), {.t_end = nan}), std::invalid_argument);
  // On the floor with zero speed, N = 0 and N' = 0 (exact in binary: k d = 256 / 32 = -m1 g): a
  // tangency the reference reports rather than guesses at.
  ChainState tangent;
  tangent.q << 0.0, 1.03125;
  CHECK_THROWS_WITH(
      ChainReference(Chain{1.0, 1.0, 256.0, 1.0, -8.0, 0.0, 0.5}, tangent, {.t_end = 1}),
      Catch::Contains("contact force and its rate both 0"));
  // Budgets: too few impacts allowed for the run.
  CHECK_THROWS_WITH(ChainReference(good, dropped(), {.t_end = 50, .max_impacts = 10}),
                    Catch::Contains("more than 10 impacts"));
  // A run whose values overflow stops at the step that produced them, naming the state.
  Chain overflowing = good;
  overflowing.g = -1e300;
  ChainMoreauJean stepper(overflowing, 1e10, MoreauJeanParams{});
  CHECK_THROWS_WITH(simulate(stepper, dropped(), Grid{1e10, 10},
                             [](std::int64_t, const ChainState&, const StepInfo&) {}),
                    Catch::Contains("step 0") && Catch::Contains("non-finite result x1 = "));
}

TEST_CASE("chain: the example of docs/library.md runs", "[chain][regression]") {
  // docs/library.md, "Beyond one particle: a two-mass chain", as written there.
  const impact::Chain chain{
      .m1 = 1, .m2 = 0.5, .k = 200, .ell = 1, .g = -9.81, .phi = 0, .cor = 0.8};
  impact::ChainState start;
  start.q << 1.0, 2.0;  // x1, x2; v = 0
  impact::ChainMoreauJean stepper(chain, 1e-3, impact::MoreauJeanParams{.theta = 0.5});
  std::int64_t contact_steps = 0;
  const RunSummary summary =
      impact::simulate(stepper, start, impact::Grid::covering(2.0, 1e-3),
                       [&](std::int64_t, const impact::ChainState&, const impact::StepInfo& info) {
                         contact_steps += info.contact_force > 0;
                       });
  CHECK(summary.steps == 2000);
  CHECK(summary.contact_steps == contact_steps);
  CHECK(contact_steps >= 5);
}
