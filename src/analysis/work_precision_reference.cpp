#include "analysis/work_precision_reference.hpp"

#include <stdexcept>
#include <string>

#include "impact/loop/simulate.hpp"
#include "impact/model/event.hpp"
#include "impact/run/any_stepper.hpp"
#include "impact/run/step_events.hpp"

namespace impact {

std::string_view reference_method(const Model& model) {
  return reference_for(model).name;
}

std::int64_t count_impacts(const Scene& scene) {
  std::int64_t impacts = 0;
  AnyStepper stepper = make_stepper(scene);
  attach_event_sink(stepper, [&](const Event& e) { impacts += e.kind == EventKind::impact; });
  simulate(stepper, scene.initial, scene.grid, [](std::int64_t, const State&, const StepInfo&) {});
  return impacts;
}

ReferenceTrajectory reference_trajectory(const Model& model, const State& initial,
                                         const Grid& grid) {
  AnyStepper stepper = make_stepper(model, grid.h, reference_for(model).defaults);
  ReferenceTrajectory reference;
  reference.states.reserve(static_cast<std::size_t>(grid.steps) + 1);
  attach_event_sink(stepper, [&reference](const Event& event) {
    if (event.kind == EventKind::impact && !reference.first_impact)
      reference.first_impact = event.t;
  });
  simulate(stepper, initial, grid, [&reference](std::int64_t, const State& s, const StepInfo&) {
    reference.states.push_back(s);
  });
  return reference;
}

}  // namespace impact
