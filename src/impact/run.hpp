// The time loop shared by every solver: t_l = l h (never accumulated), a finite-value and
// convergence check after each step, and an observer that sees every step, so output streams in
// O(1) memory (a CSV writer that decimates, an error accumulator, or nothing).
#pragma once

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "impact/model.hpp"
#include "impact/registry.hpp"

namespace impact {

// A step produced a non-finite value or an iterative solve did not converge (exit code 1).
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
  NumericalError(const std::string& what, bool converged)
      : std::runtime_error(what), converged(converged) {}
  bool converged = true;  // false: a solve did not converge; true: a non-finite value
};

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

// The same with the stepper's own account of a solve that did not converge, for a stepper that
// gives one (std::string failure_reason() const: which rule failed, the residual reached).
template <class Stepper>
[[noreturn, gnu::cold, gnu::noinline]] void throw_step_failure(const Stepper& stepper,
                                                              std::int64_t l, double t, State s,
                                                              StepInfo info) {
  if constexpr (requires { stepper.failure_reason(); })
    if (!info.converged) throw_step_failure(l, t, s, info, stepper.failure_reason());
  throw_step_failure(l, t, s, info);
}

namespace detail {

template <class Stepper, class Observer>
[[gnu::always_inline]] inline RunSummary step_loop(Stepper& stepper, const State& initial,
                                                   const Grid& grid, Observer& observe) {
  RunSummary summary;
  State s = initial;
  observe(std::int64_t{0}, s, StepInfo{});
  for (std::int64_t l = 0; l < grid.steps; ++l) {
    const StepInfo info = stepper.step(s, l);
    if (!(std::isfinite(s.u) && std::isfinite(s.v) && std::isfinite(info.contact_force)) ||
        !info.converged) [[unlikely]]
      throw_step_failure(stepper, l, grid.t(l), s, info);
    summary.contact_steps += info.contact_force > 0;
    summary.iterations += info.iterations;
    summary.max_iterations = info.iterations > summary.max_iterations ? info.iterations
                                                                       : summary.max_iterations;
    observe(l + 1, s, info);
  }
  summary.steps = grid.steps;
  return summary;
}

}  // namespace detail

// observe(l, state at t_l, info of the step that ended at t_l; zero for l = 0).
//
// The step loop is where a run spends its time, so it is written for the compiler. Measured with
// `impact run` on Figure 3's scene, 1e8 steps, decimated output, ns per step for direct /
// moreau_jean / fb_newton: 10.2 / 8.3 / 20.5 before, 2.8 / 2.4 / 15.4 after these points and the
// observer of src/cli/main.cpp (experiments/performance/README.md):
//  - the loop is a function of its own (noinline), so that its registers are allocated for the
//    loop alone and not inside a large caller;
//  - it steps a local copy of the stepper, moved back when the run ends: a stepper that other code
//    can reach (in a variant, on the heap) has its members kept in memory across the loop, a local
//    one in registers. Moving it back also on an exception (a scope guard, or a catch) made GCC
//    keep the local in memory as well (7.6 or 7.4 instead of 3.0 ns per direct step on Figure 4's
//    COR scene), so after a NumericalError the stepper is valid but moved from: destroy it or
//    assign it, but make a new one to run again;
//  - each step's StepInfo is a fresh constant: assigned to a variable living across the loop, GCC
//    copied its 13 bytes with two overlapping 8-byte moves whose load waits for the store before it
//    (store-to-load forwarding fails);
//  - the observer is inlined; it should do its rare work (a CSV row) out of line, on copies, so
//    that nothing on its common path takes the address of the loop's state.
template <class Stepper, class Observer>
[[gnu::noinline]] RunSummary simulate(Stepper& stepper, const State& initial, const Grid& grid,
                                      Observer&& observe) {
  if constexpr (std::is_move_constructible_v<Stepper> && std::is_move_assignable_v<Stepper>) {
    Stepper local = std::move(stepper);
    const RunSummary summary = detail::step_loop(local, initial, grid, observe);
    stepper = std::move(local);
    return summary;
  } else {
    // A stepper that holds references (a wrapper such as convergence.hpp's) steps in place.
    return detail::step_loop(stepper, initial, grid, observe);
  }
}

template <class Observer>
RunSummary simulate(AnyStepper& stepper, const State& initial, const Grid& grid,
                    Observer&& observe) {
  return std::visit([&](auto& s) { return simulate(s, initial, grid, observe); }, stepper);
}

}  // namespace impact
