// The time loop shared by every solver: t_l = l h (never accumulated), a finite-value and
// convergence check after each step, and an observer that sees every step, so output streams in
// O(1) memory (a CSV writer that decimates, an error accumulator, or nothing).
#pragma once

#include <array>
#include <cmath>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "impact/loop/repeats.hpp"
#include "impact/loop/stepper.hpp"
#include "impact/model/model.hpp"

namespace impact {

// A step produced a non-finite value or an iterative solve did not converge (exit code 1).
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  NumericalError(const std::string& what, bool converged)
      : std::runtime_error(what), converged(converged) {}
  bool converged = true;  // false: a solve did not converge; true: a non-finite value
};

// A run stopped because its caller asked it to (RunOutputs::stop, run_scene.hpp); not a
// std::exception, so that no catch of a run's failures takes it for one.
struct Interrupted {};

struct RunSummary {
  std::int64_t steps = 0;
  std::int64_t contact_steps = 0;  // steps with N^l > 0
  std::int64_t iterations = 0;     // total Newton iterations / ODE steps
  int max_iterations = 0;
};

// Throws NumericalError naming the step, the time and the reason, followed by `detail` when it is
// not empty. Out of line and taking copies, so that the step loop keeps its state in registers
// (measured: 12 -> 3 ns per direct step).
[[noreturn, gnu::cold, gnu::noinline]] void throw_step_failure(std::int64_t l, double t, State s,
                                                               StepInfo info);
[[noreturn, gnu::cold, gnu::noinline]] void throw_step_failure(std::int64_t l, double t, State s,
                                                               StepInfo info,
                                                               const std::string& detail);
// The same for a stepper's own state type, as `describe` spells it.
[[noreturn, gnu::cold, gnu::noinline]] void throw_step_failure(std::int64_t l, double t,
                                                               const std::string& state,
                                                               StepInfo info,
                                                               const std::string& detail);

// A stepper of StateWithInternal that says how many internal variables it follows (the general
// force kind, with_internal.hpp; event_driven): with none, a failure names u and v alone, as one
// of State does.
template <class S>
concept CountsInternal = requires(const S& stepper) {
  { stepper.internal_count() } -> std::convertible_to<std::size_t>;
};

// The same with the stepper's own account of a solve that did not converge, for a stepper that
// gives one (ExplainsFailure).
template <class S, class St>
[[noreturn, gnu::cold, gnu::noinline]] void throw_step_failure(const S& stepper, std::int64_t l,
                                                               double t, St s, StepInfo info) {
  if constexpr (std::is_same_v<St, State>) {
    if constexpr (ExplainsFailure<S>)
      if (!info.converged) throw_step_failure(l, t, s, info, stepper.failure_reason());
    throw_step_failure(l, t, s, info);
  } else {
    std::string detail;
    if constexpr (ExplainsFailure<S>)
      if (!info.converged) detail = stepper.failure_reason();
    if constexpr (CountsInternal<S>)
      if (stepper.internal_count() == 0)
        throw_step_failure(l, t, static_cast<const State&>(s), info, detail);
    throw_step_failure(l, t, describe(s), info, detail);
  }
}

namespace detail {

// Stands for a stepper that gives no account of a failure, so that the step loop's cold path
// gets no reference to a stepper that has nothing to say (see simulate() on addresses).
struct NoAccount {};
// The same for one that gives its internal variables' count alone (CountsInternal), by value.
struct InternalCount {
  std::size_t n;
  std::size_t internal_count() const { return n; }
};

template <class S, class St>
[[noreturn, gnu::always_inline]] inline void fail_step(const S& stepper, std::int64_t l, double t,
                                                       const St& s, const StepInfo& info) {
  if constexpr (ExplainsFailure<S>)
    throw_step_failure(stepper, l, t, s, info);
  else if constexpr (CountsInternal<S>)
    throw_step_failure(InternalCount{stepper.internal_count()}, l, t, s, info);
  else
    throw_step_failure(NoAccount{}, l, t, s, info);
}

// Step l's accounting: the finite-value and convergence check, the summary and the observer.
// The check adds the three values and tests the sum (finite exactly when all three are, or one
// overflowed, which the exact test then clears): one test instead of three (measured on an Intel
// Xeon family 6 model 167: 3.2 -> 3.1 ns per direct step in free flight).
// Another state type (StateOf) says itself whether it is finite.
template <class S, class St, class Observer>
[[gnu::always_inline]] inline void account(const S& stepper, std::int64_t l, const St& s,
                                           const StepInfo& info, const Grid& grid,
                                           RunSummary& summary, Observer& observe) {
  if constexpr (std::is_same_v<St, State>) {
    if (!std::isfinite(s.u + s.v + info.contact_force) || !info.converged) [[unlikely]]
      if (!(std::isfinite(s.u) && std::isfinite(s.v) && std::isfinite(info.contact_force)) ||
          !info.converged)
        fail_step(stepper, l, grid.t(l), s, info);
  } else {
    if (!s.finite() || !std::isfinite(info.contact_force) || !info.converged) [[unlikely]]
      fail_step(stepper, l, grid.t(l), s, info);
  }
  summary.contact_steps += scheme_force(info) > 0;
  summary.iterations += info.iterations;
  summary.max_iterations =
      info.iterations > summary.max_iterations ? info.iterations : summary.max_iterations;
  observe(l + 1, s, info);
}

// The stepper's steps from l + 1 on repeat with period p (RepeatingSteps): takes one period,
// recording it, then hands the observer the whole periods that fit before the end from the
// record, without stepping, and moves the stepper on by them. Returns the last step taken or
// handed on.
template <class S, class Observer>
[[gnu::always_inline]] inline std::int64_t repeat_steps(S& stepper, StateOf<S>& s, std::int64_t l,
                                                        std::int64_t p, const Grid& grid,
                                                        RunSummary& summary, Observer& observe) {
  if (p > kMaxRepeatPeriod) return l;  // not kept: the loop steps on
  std::array<std::pair<StateOf<S>, StepInfo>, kMaxRepeatPeriod> period;
  std::int64_t contact_steps = 0, iterations = 0;  // in one period
  for (std::int64_t k = 0; k < p; ++k) {
    if (l + 1 == grid.steps) return l;
    const StepInfo info = stepper.do_step(s, ++l);
    account(stepper, l, s, info, grid, summary, observe);
    period[static_cast<std::size_t>(k)] = {s, info};
    contact_steps += scheme_force(info) > 0;
    iterations += info.iterations;
  }
  const std::int64_t periods = (grid.steps - 1 - l) / p;
  for (std::int64_t k = 0; k < periods; ++k)
    for (std::int64_t j = 0; j < p; ++j) {
      const auto& [state, info] = period[static_cast<std::size_t>(j)];
      observe(l + 2 + k * p + j, state, info);
    }
  stepper.skip_steps(periods * p);
  summary.contact_steps += periods * contact_steps;
  summary.iterations += periods * iterations;
  return l + periods * p;
}

template <Stepper S, class Observer>
[[gnu::always_inline]] inline RunSummary step_loop(S& stepper, const StateOf<S>& initial,
                                                   const Grid& grid, Observer& observe) {
  RunSummary summary;
  StateOf<S> s = initial;
  stepper.initialize(s, 0);
  observe(std::int64_t{0}, s, StepInfo{});
  for (std::int64_t l = 0; l < grid.steps; ++l) {
    const StepInfo info = stepper.do_step(s, l);
    account(stepper, l, s, info, grid, summary, observe);
    if constexpr (RepeatingSteps<S>)
      if (const std::int64_t p = stepper.repeat_period(); p > 0) [[unlikely]]
        l = repeat_steps(stepper, s, l, p, grid, summary, observe);
  }
  summary.steps = grid.steps;
  return summary;
}

}  // namespace detail

// An observer with `static constexpr bool kStepsLocally = true` (and copyable): see simulate().
template <class Observer>
concept StepsLocally = std::remove_cvref_t<Observer>::kStepsLocally;

// Initializes the stepper at (t_0, initial) and runs it over the grid; observe(l, state at t_l,
// info of the step that ended at t_l; zero for l = 0) sees every step.
//
// The step loop is where a run spends its time, so it is written for the compiler (the measured
// effect of each point is in experiments/performance/README.md):
//  - the loop is a function of its own (noinline), so that its registers are allocated for the
//    loop alone;
//  - it steps a local copy of the stepper, moved back when the run ends: the members of a stepper
//    that other code can reach (in a variant, on the heap) stay in memory across the loop, those of
//    a local one in registers. Moving it back on an exception too made GCC keep the local in
//    memory, so after a NumericalError the stepper is valid but moved from: initialize a new one;
//  - each step's StepInfo is a fresh constant (assigned to a variable living across the loop, its
//    13 bytes were copied with overlapping moves that defeat store-to-load forwarding);
//  - the observer is inlined; it should do its rare work (a CSV row) out of line, on copies, so
//    that nothing on its common path takes the address of the loop's state;
//  - every function on a step's path (do_step, its kernels, the observer's call operator, the
//    repeat watch) is always_inline, and what runs out of line takes copies and returns values:
//    GCC's inliner gives up in a unit that instantiates many loops (run_scene.cpp), and one call
//    that receives the address of the local stepper or observer keeps it in memory for the whole
//    loop, a store-to-load round trip a step. Measured through `impact run` on an AMD EPYC family
//    26 model 2, 1e8 steps in free flight: direct 4.7 -> 2.2 ns, moreau_jean 8.2 -> 2.6 ns a step
//    (simulate() alone: 1.7 and 2.2);
//  - that holds on the loop's exception path too, where the local is destroyed: a stepper that
//    owns heap memory holds it in a HeapValue and inlines its destructor (heap_value.hpp);
//  - an observer that updates running values of its own at every step and says so (StepsLocally)
//    is stepped as a local copy too, copied back when the run ends, for the same reason;
//  - a stepper whose steps have begun to repeat (RepeatingSteps: a particle resting or chattering
//    on the floor) is stepped through one period only; the observer sees the other periods from
//    it, with the same bits, so that a long rest costs the observer's work alone.
template <Stepper S, class Observer>
[[gnu::noinline]] RunSummary simulate(S& stepper, const StateOf<S>& initial, const Grid& grid,
                                      Observer&& observe) {
  if constexpr (std::is_move_constructible_v<S> && std::is_move_assignable_v<S>) {
    S local = std::move(stepper);
    RunSummary summary;
    if constexpr (StepsLocally<Observer>) {
      std::remove_cvref_t<Observer> watcher = observe;
      summary = detail::step_loop(local, initial, grid, watcher);
      observe = watcher;
    } else {
      summary = detail::step_loop(local, initial, grid, observe);
    }
    stepper = std::move(local);
    return summary;
  } else {
    // A stepper that holds references (a wrapper that tallies or pairs steppers) steps in place.
    return detail::step_loop(stepper, initial, grid, observe);
  }
}

// A stepper that follows internal variables (StateOf is StateWithInternal), from the particle's
// initial state: the internal variables start at the model's initial values (initial_state); its
// observer sees the full state (an observer of State sees the particle's).
template <Stepper S, class Observer>
requires(!std::is_same_v<StateOf<S>, State>) && requires(const S& s, const State& x) {
  { s.initial_state(x) } -> std::same_as<StateOf<S>>;
}
RunSummary simulate(S& stepper, const State& initial, const Grid& grid, Observer&& observe) {
  return simulate(stepper, stepper.initial_state(initial), grid, observe);
}

}  // namespace impact
