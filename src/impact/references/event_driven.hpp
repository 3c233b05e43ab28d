// The method event_driven: the exact solution of (2-1)-(2-4) for any body force f(t), a muparser
// expression above all, followed event by event (ExactMarch, exact_march.hpp) with its free
// flights integrated by GSL odeiv2 rk8pd (OdeLaw, ode_flight.hpp: tolerances, dense output, the
// force bound per ODE step and what it does and does not guarantee), sampled on t = l h. It is the
// reference for an expression force, as exact is for a constant or harmonic one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "impact/methods/method_params.hpp"
#include "impact/model/event.hpp"
#include "impact/model/model.hpp"
#include "impact/references/exact_march.hpp"
#include "impact/references/ode_flight.hpp"

namespace impact {

// The state it steps is StateWithInternal: the model's internal variables (model.hpp) or a
// bonding field's beta and D, integrated with the flight and on the floor (ode_flight.hpp) and
// sampled with u and v; the ODE has 2 + m equations, m = 0 without them (z then stays zero).
class EventDriven {
 public:
  using StateType = StateWithInternal;

  // Throws std::invalid_argument for parameters out of range or an expression that does not parse.
  EventDriven(const Model& model, double h, const EventDrivenParams& params);

  // The full initial state of a run from the particle's: z at the model's initial values.
  StateWithInternal initial_state(const State& s) const { return with_internal(model_, s); }
  void initialize(const StateWithInternal& s, std::int64_t l);
  // Samples the solution at t_{l+1} = (l + 1) h; N^l = impulse in (t_l, t_{l+1}] / h.
  StepInfo do_step(StateWithInternal& s, std::int64_t l);
  // Receives the impacts, sticks and lifts in increasing t as the samples pass them.
  void set_event_sink(EventSink sink);
  // The end of the run (make_stepper of a scene sets it): f is evaluated up to it and no further
  // (ode_flight.hpp). Takes effect at the next initialize().
  void set_end(double end) { settings_.end = end; }

  // Why the last step did not converge: the budget that was used up, the ODE step that failed or
  // the contact search that stalled, with what to do; for simulate()'s message.
  std::string failure_reason() const;
  // The internal variables it follows (with a bonding field's two): 0 for the particle alone,
  // whose failure message then names u and v alone (simulate.hpp).
  std::size_t internal_count() const { return internal_count_; }

 private:
  Model model_;
  double h_;
  EventDrivenParams params_;
  OdeSettings settings_;
  std::size_t internal_count_;
  std::int64_t l0_ = 0, event_limit_ = 0;
  std::optional<ExactMarch<OdeLaw>> track_;
  EventSink sink_;
};

}  // namespace impact
