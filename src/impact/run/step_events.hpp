// The events of a run (event.hpp) for `impact run --events FILE`. A stepper that knows its events
// exactly reports them itself through `void set_event_sink(EventSink)`; for a time-stepper they are
// read off its steps, in O(1) memory, by these rules:
//  - a contact step is one by the rule of contact.hpp (N^l > u^{l+1} - phi: the force branch of
//    (4-3), which fb_newton's smoothed pair reaches only within sqrt(eps/2) of the floor) whose
//    contact impulse is above rounding, h N^l > 8 eps (|v^l| + |v^{l+1}|): the impulse is a
//    difference of velocities, h N^l = v^{l+1} - v^l - h fbar_l (4-1), with |h fbar_l| <= |v^l| +
//    |v^{l+1}| on a free step, so a free step's computed impulse is a few roundings of those;
//  - an impact is a contact step after a free step (or at the start) that reaches the floor moving
//    towards it; its time is t_l + s, s the first root of (u^l - phi) + v^l s + fbar_l s^2/2 in
//    [0, h] (the free flight under the step's mean force: exact for a scheme that flies in closed
//    form under a constant f), v_before the velocity there, v_after = v^{l+1};
//  - a stick is a contact step that ends at rest, |v^{l+1}| <= h |fbar_l| (less than one step of
//    the body force), followed by another such step (a compliant contact, penalty's, passes v = 0
//    in one step at its deepest point); it is dated t_l if the step started at rest too, else
//    t_{l+1} (v_before = v_after = 0);
//  - a lift is the first free step after a stick, dated t_l, the last time the particle was held.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "impact/forces/force.hpp"
#include "impact/loop/stepper.hpp"
#include "impact/model/event.hpp"
#include "impact/model/model.hpp"

namespace impact {

// Gives `stepper` the sink if it knows its events exactly (has set_event_sink); returns whether it
// did, else the events are to be read off its steps with an StepEvents.
template <Stepper S>
bool attach_event_sink(S& stepper, const EventSink& sink) {
  if constexpr (EventSource<S>) {
    stepper.set_event_sink(sink);
    return true;
  } else {
    return false;
  }
}

// The events of a time-stepper's run by the rules above, as an observer of simulate().
class StepEvents {
 public:
  StepEvents(const Model& model, double h, EventSink sink);

  // The state at t_l and the StepInfo of the step that ended there (l = 0: the initial state).
  void operator()(std::int64_t l, const State& s, const StepInfo& info);
  // The same with internal variables: an event inside step l - 1 carries them interpolated
  // linearly between t_{l-1} and t_l at its time (first order, as the steppers that follow them).
  void operator()(std::int64_t l, const StateWithInternal& s, const StepInfo& info);

 private:
  void emit(Event event) const;
  enum class Phase { free, contact, pending_stick, stuck };
  void contact_step(std::int64_t l, const State& after, double mean_force);
  double floor_time(double mean_force) const;

  ForceFunction force_;
  std::size_t carried_;  // event_variables(model).size()
  double h_;
  EventSink sink_;
  Phase phase_ = Phase::free;
  State before_;  // the state at t_{l-1}
  double stick_t_ = 0.0;
  std::int64_t l_ = 0;                                       // the step's end, t_l
  std::array<double, kMaxInternal> z_before_{}, z_after_{};  // at t_{l-1} and t_l
};

// The names of an event's internal values (Event::internal), the columns after v_after of the
// events CSV: the model's internal variables, or a bonded model's beta and D (model.hpp).
std::vector<std::string> event_variables(const Model& model);

// The CSV of `impact run --events`: the header t,kind,v_before,v_after (then event_variables), and
// one row per event with numbers in round-trip precision (17 significant digits), the first
// `internal` internal values last. write_event returns the row's bytes.
void write_event_header(std::FILE* out, const Model& model = {});
std::size_t write_event(std::FILE* out, const Event& event, std::size_t internal = 0);

}  // namespace impact
