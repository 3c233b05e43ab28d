// The stepper interface, in the spirit of Boost.Odeint's steppers, as concepts:
//   S(const Model&, [const ContactLaw&,] double h, const Params&);  // the law: time-steppers
//   void initialize(const State& s, std::int64_t l); // (re)start at t_l = l h from s
//   StepInfo do_step(State& s, std::int64_t l);      // s: the state at t_l that the stepper
//                                                    // produced (or was initialized with);
//                                                    // advanced to t_{l+1}
// A stepper over another state than the one particle's (the two-mass chain, chain.hpp) names it
// `using StateType = ...;`: simulate() (simulate.hpp) then steps that state; the type needs
// `bool finite() const` and `std::string describe(const StateType&)` for the failure message.
// A stepper may carry state of its own between steps (direct's free-flight anchor, fb_newton's
// gap, penalty's ODE driver); to start from any other state, call initialize() again. What else
// a new method touches: ARCHITECTURE.md, "Where a new thing goes".
#pragma once

#include <concepts>
#include <cstdint>
#include <string>

#include "impact/model/event.hpp"
#include "impact/model/model.hpp"

namespace impact {

// The state a stepper advances: its StateType, else the one particle's State.
template <class S>
struct StepperState {
  using type = State;
};
template <class S>
requires requires {
  typename S::StateType;
}
struct StepperState<S> {
  using type = typename S::StateType;
};
template <class S>
using StateOf = typename StepperState<S>::type;

template <class S>
concept Stepper = requires(S& stepper, StateOf<S>& s, const StateOf<S>& cs, std::int64_t l) {
  stepper.initialize(cs, l);
  { stepper.do_step(s, l) } -> std::same_as<StepInfo>;
};

// A stepper of the one particle's state alone (no internal variables, no other body): what an
// analysis that steps a method by hand, beside another, is written for.
template <class S>
concept ParticleStepper = Stepper<S> && std::same_as<StateOf<S>, State>;

// A stepper that knows its events exactly and reports them (exact, event_driven); the others' are
// read off their steps (step_events.hpp).
template <class S>
concept EventSource = Stepper<S> && requires(S& stepper, const EventSink& sink) {
  stepper.set_event_sink(sink);
};

// A stepper that can say why a solve did not converge (which rule failed, the residual reached).
template <class S>
concept ExplainsFailure = requires(const S& stepper) {
  { stepper.failure_reason() } -> std::convertible_to<std::string>;
};

// A stepper whose steps can repeat says so (optional; repeats.hpp): after do_step(s, l),
// repeat_period() is p in 1..kMaxRepeatPeriod when the steps from l + 1 on repeat with period p,
// states and infos bit for bit, else 0; skip_steps(n), n a multiple of p, moves the stepper on by
// n steps as if it had taken them. simulate() then takes one period and hands the rest of the run
// to the observer from it without stepping.
template <class S>
concept RepeatingSteps = Stepper<S> && requires(S& stepper, const S& c, std::int64_t n) {
  { c.repeat_period() } -> std::convertible_to<std::int64_t>;
  stepper.skip_steps(n);
};

}  // namespace impact
