// The reference of --against exact and of every error measure (error_norms.hpp) samples the
// closed form flight by flight; each sample must be ExactSolution::at() bit for bit, through the
// Zeno accumulation and the rest after it, for every grid.
#include <bit>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdint>

#include "impact/loop/simulate.hpp"
#include "impact/references/exact.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/error_norms.hpp"

using impact::Model;
using impact::State;

TEST_CASE("reference sampling: flight by flight is at() bit for bit", "[exact][regression]") {
  struct Case {
    Model model;
    State initial;
    double T;
  };
  const Case cases[] = {
      {{0.0, -9.80665, 0.75, {}, {}}, {5.0, -1.0}, 10.0},   // Figure 4 with COR: Zeno at 7.0 s
      {{0.0, -9.80665, {}, {}, {}}, {5.0, -1.0}, 10.0},     // elastic: bounces forever
      {{0.0, -9.80665, 0.0, {}, {}}, {1.0, 0.0}, 2.0},      // plastic: rests at the impact
      {{1e6, -9.80665, 0.9, {}, {}}, {1e6 + 1, 3.0}, 8.0},  // a far floor, COR near 1
      {{0.0, 2.0, 0.5, {}, {}}, {0.5, -3.0}, 3.0},          // an upward force: one impact
  };
  for (const Case& c : cases)
    for (const double h : {1e-3, 3.7e-4, 1e-5}) {
      INFO("u0 = " << c.initial.u << ", f = " << c.model.f << ", h = " << h);
      const impact::ExactSolution exact(c.model, c.initial);
      impact::ReferenceSolution reference(c.model, c.initial, c.T);
      const impact::Grid grid = impact::Grid::covering(c.T, h);
      std::int64_t first_difference = -1;
      for (std::int64_t l = 0; l <= grid.steps && first_difference < 0; ++l) {
        const State a = reference.at(grid.t(l)), b = exact.at(grid.t(l));
        if (std::bit_cast<std::uint64_t>(a.u) != std::bit_cast<std::uint64_t>(b.u) ||
            std::bit_cast<std::uint64_t>(a.v) != std::bit_cast<std::uint64_t>(b.v))
          first_difference = l;
      }
      CHECK(first_difference == -1);
    }
}

TEST_CASE("reference sampling: h sum |v - v_exact| at rest is the plain sum bit for bit",
          "[exact][regression]") {
  // The error observer skips the product h dv when dv is subnormal and cannot change the sum (a
  // particle at rest carries v = +-2^-1073); the sum must be the one every product would give.
  const Model model{0.0, -9.80665, 0.75, {}, {}};  // Figure 4 with COR: at rest from 7.0 s
  const State initial{5.0, -1.0};
  for (const double h : {1e-3, 3.7e-4}) {
    const impact::Grid grid = impact::Grid::covering(12.0, h);
    impact::ErrorObserver errors(model, initial, grid);
    impact::ExactSolution exact(model, initial);
    double plain = 0;
    std::int64_t subnormal_steps = 0;
    impact::AnyStepper stepper = impact::make_stepper(model, h, impact::DirectParams{});
    const impact::RunSummary run = impact::simulate(
        stepper, initial, grid, [&](std::int64_t l, const State& s, const impact::StepInfo& info) {
          errors(l, s, info);
          const double dv = std::fabs(s.v - exact.at(grid.t(l)).v);
          subnormal_steps += dv > 0 && dv < 0x1p-1022;
          plain += h * dv;
        });
    INFO("h = " << h);
    CHECK(subnormal_steps > 1000);
    CHECK(std::bit_cast<std::uint64_t>(errors.result(run).l1_v) ==
          std::bit_cast<std::uint64_t>(plain));
  }
}
