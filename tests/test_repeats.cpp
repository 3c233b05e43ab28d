// Repeating steps (repeats.hpp): a run that hands the periods of a resting or chattering particle
// to the observer without stepping reports exactly what the run that takes every step reports:
// every step's state and info bit for bit, in order, and the same RunSummary.
#include <bit>
#include <catch2/catch.hpp>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "impact/loop/simulate.hpp"
#include "impact/steppers/direct.hpp"
#include "impact/steppers/fb_newton.hpp"
#include "impact/steppers/moreau_jean.hpp"

using namespace impact;

namespace {

// The stepper without its RepeatingSteps capability: simulate() takes every step.
template <class Stepper>
struct EveryStep {
  Stepper stepper;
  void initialize(const State& s, std::int64_t l) { stepper.initialize(s, l); }
  StepInfo do_step(State& s, std::int64_t l) { return stepper.do_step(s, l); }
};

// The stepper with its capability, counting the steps it takes.
template <class Stepper>
struct Counted {
  Stepper stepper;
  std::int64_t* taken;
  void initialize(const State& s, std::int64_t l) { stepper.initialize(s, l); }
  StepInfo do_step(State& s, std::int64_t l) {
    ++*taken;
    return stepper.do_step(s, l);
  }
  std::int64_t repeat_period() const { return stepper.repeat_period(); }
  void skip_steps(std::int64_t n) { stepper.skip_steps(n); }
};

struct Record {
  std::vector<std::int64_t> words;  // l, then the bits of u, v, N and the iterations, per step
  RunSummary summary;
};

void add(Record& r, std::int64_t l, const State& s, const StepInfo& i) {
  for (const std::int64_t w :
       {l, std::bit_cast<std::int64_t>(s.u), std::bit_cast<std::int64_t>(s.v),
        std::bit_cast<std::int64_t>(i.contact_force), std::int64_t{i.iterations}})
    r.words.push_back(w);
}

// The run, then 20 more steps taken one by one: the stepper is where the run left it.
template <class Stepper>
Record record(Stepper& stepper, const State& initial, const Grid& grid) {
  Record r;
  State last = initial;
  r.summary =
      simulate(stepper, initial, grid, [&](std::int64_t l, const State& s, const StepInfo& i) {
        add(r, l, s, i);
        last = s;
      });
  for (std::int64_t l = grid.steps; l < grid.steps + 20; ++l) {
    const StepInfo info = stepper.do_step(last, l);
    add(r, l + 1, last, info);
  }
  return r;
}

// Runs the stepper both ways; the number of steps the repeating run took.
template <class Stepper>
std::int64_t compare(const Stepper& stepper, const State& initial, const Grid& grid) {
  std::int64_t taken = 0;
  EveryStep<Stepper> every_step{stepper};
  Counted<Stepper> counted{stepper, &taken};
  const Record every = record(every_step, initial, grid);
  const Record repeating = record(counted, initial, grid);
  taken -= 20;
  REQUIRE(repeating.words.size() == every.words.size());
  for (std::size_t k = 0; k < every.words.size(); ++k)
    if (repeating.words[k] != every.words[k])
      FAIL("step " << every.words[k / 5 * 5] << ": word " << k % 5 << " differs");
  CHECK(repeating.summary.steps == every.summary.steps);
  CHECK(repeating.summary.contact_steps == every.summary.contact_steps);
  CHECK(repeating.summary.iterations == every.summary.iterations);
  CHECK(repeating.summary.max_iterations == every.summary.max_iterations);
  return taken;
}

// All three steppers on one model; the fewest steps any of them took.
std::int64_t compare_all(const Model& model, const State& initial, const Grid& grid) {
  std::int64_t fewest = grid.steps;
  for (const std::int64_t taken : {compare(Direct(model, grid.h, {}), initial, grid),
                                   compare(FbNewton(model, grid.h, {}), initial, grid),
                                   compare(MoreauJean(model, grid.h, {}), initial, grid)})
    fewest = std::min(fewest, taken);
  return fewest;
}

}  // namespace

TEST_CASE("Figure 4 at rest and in chatter: the repeating run reports every step as stepped",
          "[repeats][regression]") {
  const Model cor{0.0, -9.80665, 0.75}, no_cor{0.0, -9.80665, std::nullopt};
  for (const Model& model : {cor, no_cor})
    // Odd lengths, so that the run ends inside a period; 30 s: at rest from ~7 s.
    for (const std::int64_t steps : {30001, 30002, 30003}) {
      INFO("COR " << model.cor.value_or(-1) << ", " << steps << " steps");
      const std::int64_t taken = compare_all(model, State{5.0, -1.0}, Grid{1e-3, steps});
      if (model.cor) CHECK(taken < 15000);  // at rest from ~7 s: the rest is handed on
    }
}

TEST_CASE("a run that starts at rest, and runs too short to hand anything on",
          "[repeats][regression]") {
  const Model model{0.0, -9.80665, 0.75};
  const State rest{0.0, 0x1p-1073};  // Figure 4's resting state (restitution.hpp)
  for (std::int64_t steps = 0; steps <= 12; ++steps) {
    INFO(steps << " steps");
    compare_all(model, rest, Grid{1e-3, steps});
  }
  CHECK(compare_all(model, rest, Grid{1e-3, 1'000'000}) < 20);
}

TEST_CASE("random scenes: the repeating run reports every step as stepped", "[repeats][property]") {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 60; ++i) {
    Model model;
    model.phi = i % 3 == 0 ? 0.0 : 2.0 * unit(rng) - 1.0;
    const double forces[] = {-9.80665, -20.0 * unit(rng), 5.0 * unit(rng), 0.0};
    model.f = forces[i % 4];
    if (i % 5 != 4) model.cor = i % 5 == 0 ? 0.75 : unit(rng);
    const State initial{model.phi + (i % 7 == 0 ? 0.0 : 3.0 * unit(rng)), 4.0 * unit(rng) - 2.0};
    const double h = i % 2 ? 1e-3 : 1e-4 * (1 + unit(rng));
    INFO("scene " << i << ": phi " << model.phi << ", f " << model.f << ", COR "
                  << model.cor.value_or(-1) << ", h " << h);
    compare_all(model, initial, Grid{h, 20000 + i});
  }
}
